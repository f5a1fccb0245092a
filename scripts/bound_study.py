#!/usr/bin/env python3
"""How far the computed model errors of the D-dependent curves can be tightened
(docs/judging.md, "How far the computed bounds can be tightened").

Every judged MSD, MSD ratio, D ratio and TAMSD of a kinetic scene carries the model error
Dps = max(|kinetic - paper|, |kinetic - sonine1|) / |kinetic| per point (the scene's correction_from), plus
the quantity's `relative` (deviations.tsv column model_error).
The tighter candidate is the sum of the kinetic level's LAST corrections in its two truncations:
  B = relative                                  the quantity's other computed parts (its `relative`), as in Dps
    + |L - L-sonine3| / |L|                     the last Sonine term of D (order 4 over order 3)
    + |L - L'| / |L|                            the next (or last) order of the cooling closure:
                                                L' = kinetic-cooling3 beside kinetic, kinetic beside kinetic-cooling3
with L the scene's judged level, each computed by `granmix theory --level`. For every judged point of the
given validate runs (their deviations.tsv) the script reports the largest |DSMC - theory| / |theory|, the
largest Dps and B, and the worst ratio |DSMC - theory| / (bound |theory| + z sigma) for both bounds (z = 4,
the scenes' z; the script checks it). A worst ratio above 1 means that bound would have failed a run.
Usage: scripts/bound_study.py path/to/granmix OUT_DIR [OUT_DIR ...]   (OUT_DIR: a `granmix validate --out` folder)
Output: one TSV row per scene and quantity on stdout.
"""
import collections, os, subprocess, sys, tempfile, tomllib

granmix, outdirs = sys.argv[1], sys.argv[2:]
scene_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "compare", "scenes")
d_dependent = ("msd", "msd_ratio", "D_ratio", "tamsd")


def read_tsv(path):
    lines = [l.rstrip("\n").split("\t") for l in open(path) if not l.startswith("#")]
    return lines[0], [dict(zip(lines[0], l)) for l in lines[1:]]


def key(x, species):
    return ("%.6g" % float(x), int(float(species)))


def level_table(scene_file, name, level, tmp):
    subprocess.run([granmix, "theory", scene_file, "--level", level, "--out", tmp], check=True, capture_output=True)
    head, rows = read_tsv(os.path.join(tmp, name, "theory_%s.tsv" % level))
    return {key(r[head[0]], r["species"]): r for r in rows}


print("\t".join(["scene", "quantity", "points", "max_rel", "max_Dps", "max_B", "worst_over_Dps", "worst_over_B"]))
with tempfile.TemporaryDirectory() as tmp:
    for file in sorted(os.listdir(scene_dir)):
        if not file.endswith(".toml"):
            continue
        path = os.path.join(scene_dir, file)
        scene = tomllib.load(open(path, "rb"))
        level = scene.get("theory", {}).get("level", "paper")
        quantities = [q for q in scene.get("compare", {}).get("quantities", []) if q["name"] in d_dependent]
        # The levels whose D has a Sonine order (kinetic-converged solves it without one: its sweeps are left out).
        if level not in ("kinetic", "kinetic-cooling3") or not quantities:
            continue
        if any(q.get("z", 4) != 4 for q in quantities):
            sys.exit("%s: a D-dependent quantity with z != 4 (the script assumes 4)" % file)
        name = scene["scene"]["name"]
        judged = level_table(path, name, level, tmp)
        last_D = level_table(path, name, level + "-sonine3", tmp)
        closure = level_table(path, name, "kinetic-cooling3" if level == "kinetic" else "kinetic", tmp)
        worst = collections.defaultdict(lambda: [0, 0.0, 0.0, 0.0, 0.0, 0.0])
        for out in outdirs:
            dev_file = os.path.join(out, name, "deviations.tsv")
            if not os.path.exists(dev_file):
                continue
            head, rows = read_tsv(dev_file)
            for r in rows:
                column = r["quantity"].split("[")[0]
                if r["judged"] != "1" or column not in d_dependent:
                    continue
                column = "D_ratio_increment" if column == "D_ratio" else column  # what a D-ratio sweep compares
                k = key(r[head[0]], r["species"])
                # the quantity's computed `relative` part (in model_error already) is added to B too
                relative = next(q.get("relative", 0.0) for q in quantities
                                if q["name"] == r["quantity"].split("[")[0] and k[1] in q.get("species", [k[1]]))
                theory, dsmc, sigma = float(r["theory"]), float(r["dsmc"]), float(r["dsmc_err"])
                mine = float(judged[k][column])
                if abs(mine / theory - 1) > 1e-9:
                    sys.exit("%s %s: the run's theory %.9g is not this build's %.9g (rerun validate)" % (name, r["quantity"], theory, mine))
                B = relative + abs(mine - float(last_D[k][column])) / abs(mine) + abs(mine - float(closure[k][column])) / abs(mine)
                Dps, gap = float(r["model_error"]), abs(dsmc - theory)
                w = worst[r["quantity"]]
                w[0] += 1
                w[1] = max(w[1], gap / abs(theory))
                w[2], w[3] = max(w[2], Dps), max(w[3], B)
                w[4] = max(w[4], gap / (Dps * abs(theory) + 4 * sigma))
                w[5] = max(w[5], gap / (B * abs(theory) + 4 * sigma))
        for q, w in worst.items():
            print("\t".join([name, q, str(w[0])] + ["%.4f" % v for v in w[1:]]))
