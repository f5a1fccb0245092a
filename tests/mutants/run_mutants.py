#!/usr/bin/env python3
"""Mutation harness: how many plausible physics bugs does the suite catch? (docs/reliability.md)

Each mutant of mutants.toml is a few exact text edits applied to a scratch copy of the committed
tree (git archive of HEAD or MUTANTS_REV, kept between runs so rebuilds are incremental; the real
tree is never edited). Per mutant the stages are: build granmix, `granmix validate --fidelity quick`
(seed 1, --confirm 0; then the failing scenes one at a time, cheapest first, each validated alone with its
confirmation at 4x the replicas up to the first that fails again: validate's verdict, docs/judging.md §2.1),
and only if validate passes, build the tests and run ctest (without the tests labelled `checkout`,
which need the git checkout and the unmutated tree); then the files are restored. Before the first
mutant, ctest runs once on the unmutated tree: a test that fails there is not counted for any mutant.
A mutant whose search text is not found exactly once is `stale`, never skipped silently.

Each mutant gets one outcome, from the first stage that does not pass:
  caught: deviation     validate exit 1 with a scene:quantity row of verdict FAIL, or a failing ctest test
  caught: solver error  validate exit 3 (a numerical failure stopped the run), or exit 1 where only
                        scenes that stopped with an error fail
  crash                 a signal, or any other exit code (a ctest test that crashed or was not run)
  timeout               a stage, or a ctest test, ran out of time
  build failed          the mutated code does not compile
  missed                every stage passes
Only the two `caught` outcomes count as caught.

Environment: MUTANTS=id1,id2 (a subset, run in that order), JOBS (build, ctest and validate
threads; default 2), MUTANTS_REV (the commit to mutate; default HEAD), MUTANTS_SCRATCH (scratch
folder), MUTANTS_TIMEOUT (seconds per stage, default 3600), MUTANTS_TEST_TIMEOUT (seconds per ctest
test, default 900), MUTANTS_RESULTS (folder of results.tsv/results.md; default this folder).

Results: one table records one commit. A full run replaces tests/mutants/results.{tsv,md}; a subset
run adds its rows only to a table of the same commit, and otherwise writes its own table into the
scratch folder, leaving the committed one alone.

Other modes:
  --check                           which mutants still apply to the working tree (no build)
  --self-test                       the outcome classification on stub stages (no build, no git)
  --generate-random N --seed S      replace the random mutants of mutants.toml with N drawn with seed S
Python 3.11 standard library only (tomllib).
"""
import datetime
import hashlib
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent
JOBS = int(os.environ.get("JOBS") or 2)
TIMEOUT = float(os.environ.get("MUTANTS_TIMEOUT") or 3600)
TEST_TIMEOUT = float(os.environ.get("MUTANTS_TEST_TIMEOUT") or 900)
REV = os.environ.get("MUTANTS_REV") or "HEAD"
RESULT_COLUMNS = ["id", "kind", "size_pct", "status", "stage", "caught_by", "seconds", "files", "models"]

DEVIATION, SOLVER, CRASH, TIMED_OUT, BUILD_FAILED, MISSED, STALE = (
    "caught: deviation", "caught: solver error", "crash", "timeout", "build failed", "missed", "stale")
OUTCOMES = [DEVIATION, SOLVER, CRASH, TIMED_OUT, BUILD_FAILED, MISSED, STALE]
CAUGHT = {DEVIATION, SOLVER}
# ctest labels the tests that cannot pass in a scratch copy `checkout` (they need .git and the unmutated tree).
SCRATCH_EXCLUDED_LABEL = "checkout"


def find_root():
    """The checkout's top folder; without git (a scratch copy), the folder two levels up."""
    r = subprocess.run(["git", "-C", str(HERE), "rev-parse", "--show-toplevel"], capture_output=True, text=True)
    return Path(r.stdout.strip()) if r.returncode == 0 else HERE.parents[1]


ROOT = find_root()


def git(*args):
    return subprocess.run(["git", "-C", str(ROOT), *args], check=True, capture_output=True, text=True).stdout.strip()


def all_mutants(path=HERE / "mutants.toml"):
    with open(path, "rb") as f:
        mutants = tomllib.load(f)["mutant"]
    for m in mutants:
        m["edits"] = [{"file": m["file"], "find": m["find"], "replace": m["replace"]}] + m.get("edit", [])
        m["kind"] = "random" if m.get("random") else "hand"
    ids = [m["id"] for m in mutants]
    if len(set(ids)) != len(ids):
        sys.exit("mutants.toml: duplicate ids")
    return mutants


def load_mutants():
    mutants = all_mutants()
    ids = [m["id"] for m in mutants]
    wanted = [s.strip() for s in os.environ.get("MUTANTS", "").split(",") if s.strip()]
    if not wanted:
        return mutants, False
    unknown = [w for w in wanted if w not in ids]
    if unknown:
        sys.exit(f"MUTANTS: unknown id(s) {', '.join(unknown)} (allowed: {', '.join(ids)})")
    return [next(m for m in mutants if m["id"] == w) for w in wanted], True


def sync_scratch(src: Path):
    """Make src hold exactly `git archive REV`, rewriting only changed files (keeps mtimes, so
    the build stays incremental)."""
    src.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.Popen(["git", "-C", str(ROOT), "archive", REV], stdout=subprocess.PIPE)
        subprocess.run(["tar", "-x", "-C", tmp], stdin=archive.stdout, check=True)
        if archive.wait() != 0:
            sys.exit(f"git archive {REV} failed")
        fresh = {p.relative_to(tmp) for p in Path(tmp).rglob("*") if p.is_file()}
        for rel in fresh:
            a, b = Path(tmp) / rel, src / rel
            if not b.is_file() or a.read_bytes() != b.read_bytes():
                b.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(a, b)
        for p in list(src.rglob("*")):
            if p.is_file() and p.relative_to(src) not in fresh:
                p.unlink()


# ---------------------------------------------------------------------------------------------
# Stages and their outcomes

def run(cmd, log: Path, cwd=None, tmp: Path | None = None, timeout=None, append=False):
    """Run cmd in a session of its own, output to log; returns (exit code, output). The exit code is
    None on a timeout (the whole process group is killed then, so no test or DSMC thread outlives its
    stage) and -N for signal N. With tmp, the command's TMPDIR is that fresh folder: the tests' fixed
    /tmp/granmix-test-* folders would otherwise be shared with any other checkout running its tests
    at the same time."""
    env = dict(os.environ, OMP_WAIT_POLICY="passive")
    if tmp is not None:
        shutil.rmtree(tmp, ignore_errors=True)
        tmp.mkdir(parents=True)
        env["TMPDIR"] = str(tmp)
    p = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         errors="replace", start_new_session=True)
    try:
        out, _ = p.communicate(timeout=TIMEOUT if timeout is None else timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, _ = p.communicate()
        rc = None
    except BaseException:  # an interrupted harness leaves nothing running
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
        raise
    if append and log.is_file():
        out = log.read_text() + out
    log.write_text(out)
    return rc, out


def signal_name(rc):
    try:
        return signal.Signals(-rc).name
    except ValueError:
        return f"signal {-rc}"


def stage_build(cmds, log: Path, what: str):
    """Configure and build: None if it builds, else (outcome, detail)."""
    log.unlink(missing_ok=True)
    for cmd in cmds:
        rc, _ = run(cmd, log, append=True)
        if rc is None:
            return TIMED_OUT, f"{what}: timeout after {TIMEOUT:g} s (see {log})"
        if rc != 0:
            return BUILD_FAILED, f"{what}: see {log}"
    return None


def validate_failures(out_dir: Path):
    """Failing scene:quantity rows of summary.tsv (verdict FAIL: failed, and failed again at its confirmation;
    a table without the verdict column: pass 0), and the scenes that stopped with an error (summary.json's
    errors) as (scene:ERROR, message)."""
    failed, errors = [], []
    tsv = out_dir / "summary.tsv"
    if tsv.is_file():
        lines = [l for l in tsv.read_text().splitlines() if l and not l.startswith("#")]
        head = lines[0].split("\t") if lines else []
        for l in lines[1:]:
            row = dict(zip(head, l.split("\t")))
            if (row["verdict"] == "FAIL") if "verdict" in row else row.get("pass") == "0":
                failed.append(f"{row['scene']}:{row['quantity']}" if row["quantity"] != "-" else row["scene"])
    js = out_dir / "summary.json"
    if js.is_file():
        for e in json.loads(js.read_text()).get("errors", []):
            name, _, msg = e.partition(": ")
            errors.append((f"{name.removesuffix('.toml')}:ERROR", msg[:200]))
    return failed, errors


def classify_validate(rc, out: str, out_dir: Path):
    """None if validate passes, else (outcome, detail)."""
    if rc == 0:
        return None
    if rc is None:
        return TIMED_OUT, f"validate: timeout after {TIMEOUT:g} s"
    if rc < 0:
        return CRASH, f"validate: {signal_name(rc)}"
    stopped = [l.split(": ", 1)[1][:200] for l in out.splitlines() if l.startswith("granmix: ")][:1]
    failed, errors = validate_failures(out_dir)
    if rc == 1 and failed:
        return DEVIATION, "validate: " + " ".join(failed + [e for e, _ in errors])
    if rc == 1 and errors:
        return SOLVER, "validate: " + " ".join(e for e, _ in errors) + f" ({errors[0][1]})"
    if rc == 3:
        return SOLVER, "validate stopped: " + (stopped[0] if stopped else "exit 3")
    return CRASH, f"validate: exit {rc}" + (f": {stopped[0]}" if stopped else " without a failing row")


def ctest_failures(out: str):
    """(name, reason) of every test in ctest's 'The following tests FAILED' list."""
    failed, on = [], False
    for line in out.splitlines():
        if "The following tests FAILED" in line:
            on = True
        elif on and " - " in line:
            name, _, reason = line.split(" - ", 1)[1].rstrip().rpartition(" (")
            failed.append((name.strip(), reason.rstrip(")")) if name else (reason.strip(), ""))
    return failed


def classify_ctest(rc, out: str, baseline=frozenset()):
    """None if every test passes, else (outcome, detail). A failing test is a catch; a test that only
    timed out or crashed is not. Tests of the baseline (those that fail on the unmutated tree) are
    not counted."""
    if rc == 0:
        return None
    if rc is None:
        return TIMED_OUT, f"ctest: timeout after {TIMEOUT:g} s"
    if rc < 0:
        return CRASH, f"ctest: {signal_name(rc)}"
    listed = ctest_failures(out)
    tests = [(n, r) for n, r in listed if n not in baseline]
    if listed and not tests:
        return None
    failed = [n for n, r in tests if r == "Failed"]
    timed_out = [n for n, r in tests if r == "Timeout"]
    crashed = [f"{n} ({r})" for n, r in tests if r not in ("Failed", "Timeout")]
    also = (["timeout: " + " | ".join(timed_out)] if timed_out else []) + (["crash: " + " | ".join(crashed)] if crashed else [])
    if failed:
        return DEVIATION, "ctest: " + " | ".join(failed) + "".join(f" [{a}]" for a in also)
    if crashed:
        return CRASH, "ctest: " + " | ".join(crashed) + (f" [timeout: {' | '.join(timed_out)}]" if timed_out else "")
    if timed_out:
        return TIMED_OUT, "ctest: " + " | ".join(timed_out)
    return CRASH, f"ctest: exit {rc} without a failing test listed"


def failing_scenes(out_dir: Path):
    """The scenes of summary.tsv with a failing row, cheapest DSMC first (their confirmation order)."""
    cost = {}
    tsv = out_dir / "summary.tsv"
    lines = [l for l in tsv.read_text().splitlines() if l and not l.startswith("#")] if tsv.is_file() else []
    head = lines[0].split("\t") if lines else []
    for l in lines[1:]:
        row = dict(zip(head, l.split("\t")))
        if row.get("pass") == "0":
            cost[row["scene"]] = float(row.get("dsmc_seconds") or 0)
    return sorted(cost, key=lambda k: (cost[k], k))


def confirm_validate(first, confirm, logs: Path, mid: str, cwd=None):
    """validate's confirmation, one failing scene at a time, cheapest first, up to the first that fails again
    (docs/judging.md §2.1): validate's own verdict with no more DSMC than that verdict needs. `first` is the
    deviation found with --confirm 0; confirm(scene) gives the command that validates the scene alone with
    its confirmation, and the folder it writes. (outcome, detail), or None when no failure repeats."""
    for scene in first:
        cmd, out_dir = confirm(scene)
        rc, out = run(cmd, logs / f"{mid}.confirm-{scene}.log", cwd=cwd)
        r = classify_validate(rc, out, out_dir)
        if r:
            return r[0], r[1].replace("validate: ", "validate (confirmed): ", 1)
    return None


def run_stages(build_cmds, validate_cmd, build_tests_cmds, ctest_cmd, logs: Path, mid: str, out_dir: Path,
               cwd=None, ctest_cwd=None, ctest_tmp=None, baseline=frozenset(), confirm=None):
    """The stages of one mutant, stopping at the first that does not pass: (outcome, stage, detail).
    confirm: see confirm_validate; None takes validate's first judgement as its verdict."""
    r = stage_build(build_cmds, logs / f"{mid}.build.log", "granmix")
    if r:
        return r[0], "build", r[1]
    rc, out = run(validate_cmd, logs / f"{mid}.validate.log", cwd=cwd)
    r = classify_validate(rc, out, out_dir)
    unconfirmed = ""
    if r and r[0] == DEVIATION and confirm:
        scenes = failing_scenes(out_dir)
        c = confirm_validate(scenes, confirm, logs, mid, cwd=cwd)
        if c is None:
            unconfirmed = f" (validate failed at seed 1, none confirmed: {' '.join(scenes)})"
        r = c
    if r:
        return r[0], "validate", r[1]
    r = stage_build(build_tests_cmds, logs / f"{mid}.build-tests.log", "tests")
    if r:
        return r[0], "build-tests", r[1]
    rc, out = run(ctest_cmd, logs / f"{mid}.ctest.log", cwd=ctest_cwd, tmp=ctest_tmp)
    r = classify_ctest(rc, out, baseline)
    if r:
        return r[0], "ctest", r[1] + unconfirmed
    return MISSED, "", unconfirmed.strip(" ()")


def build_cmds(src: Path, bld: Path, target=None):
    configure = ["cmake", "-S", str(src), "-B", str(bld), "-DCMAKE_BUILD_TYPE=Release"]
    if shutil.which("ccache"):
        configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    return [configure, ["cmake", "--build", str(bld), f"-j{JOBS}"] + (["--target", target] if target else [])]


def apply_edits(m, src: Path):
    """(originals, None) with the edits written, or (None, reason) if the mutant is stale. All edits are
    checked on the texts in memory first: a stale mutant leaves the tree untouched."""
    originals, mutated = {}, {}
    for e in m["edits"]:
        path = src / e["file"]
        if e["file"] not in mutated:
            if not path.is_file():
                return None, f"{e['file']}: no such file"
            originals[e["file"]] = mutated[e["file"]] = path.read_text()
        n = mutated[e["file"]].count(e["find"])
        if n != 1:
            return None, f"{e['file']}: search text found {n} times: {e['find']}"
        mutated[e["file"]] = mutated[e["file"]].replace(e["find"], e["replace"])
    for f, t in mutated.items():
        (src / f).write_text(t)
    return originals, None


def ctest_cmd():
    return ["ctest", "-j", str(JOBS), "-LE", SCRATCH_EXCLUDED_LABEL, "--timeout", f"{TEST_TIMEOUT:g}"]


def baseline_failures(src: Path, bld: Path, logs: Path):
    """The tests that fail on the unmutated tree: they cannot tell a mutant from the tree, so they are not
    counted. Exits if the tests do not build or ctest does not finish."""
    r = stage_build(build_cmds(src, bld)[1:], logs / "pristine.build-tests.log", "tests")
    if r:
        sys.exit(f"mutants: the unmutated tree's tests: {r[0]} ({r[1]})")
    rc, out = run(ctest_cmd(), logs / "pristine.ctest.log", cwd=bld, tmp=bld.parent / "tmp")
    if rc is None or rc < 0 or (rc != 0 and not ctest_failures(out)):
        sys.exit(f"mutants: ctest on the unmutated tree did not finish (see {logs / 'pristine.ctest.log'})")
    return frozenset(n for n, _ in ctest_failures(out))


def run_mutant(m, src: Path, bld: Path, logs: Path, baseline=frozenset()):
    originals, why = apply_edits(m, src)
    if originals is None:
        return STALE, "", why
    try:
        with tempfile.TemporaryDirectory(prefix="granmix-mutant-") as out_dir:
            granmix = [str(bld / "granmix"), "validate", "--fidelity", "quick", "--threads", str(JOBS)]
            validate = granmix + ["--confirm", "0", "--out", out_dir, "--scenes", str(src / "compare" / "scenes")]

            def confirm(scene):
                # The scene alone in a folder .../compare/scenes beside its frozen model errors (as validate wants them).
                folder = Path(out_dir) / "confirm" / scene
                (folder / "compare" / "scenes").mkdir(parents=True, exist_ok=True)
                shutil.copy(src / "compare" / "scenes" / f"{scene}.toml", folder / "compare" / "scenes")
                table = src / "compare" / "model-errors" / f"{scene}.tsv"
                if table.is_file():
                    (folder / "compare" / "model-errors").mkdir(exist_ok=True)
                    shutil.copy(table, folder / "compare" / "model-errors")
                return granmix + ["--out", str(folder / "out"), "--scenes", str(folder / "compare" / "scenes")], folder / "out"

            # The tests are built only when validate has not caught the mutant: that saves recompiling every
            # test that includes a mutated header.
            return run_stages(build_cmds(src, bld, "granmix"), validate, build_cmds(src, bld)[1:], ctest_cmd(), logs,
                              m["id"], Path(out_dir), cwd=src, ctest_cwd=bld, ctest_tmp=bld.parent / "tmp", baseline=baseline,
                              confirm=confirm)
    finally:
        for f, t in originals.items():
            (src / f).write_text(t)


# ---------------------------------------------------------------------------------------------
# Results

def fmt_caught_by(s, limit=4):
    kind, _, rest = s.partition(": ")
    if kind not in ("validate", "ctest"):  # one message, not a list
        return s
    items = rest.split(" | ") if kind == "ctest" else rest.split(" ")
    if len(items) <= limit:
        return s
    sep = " | " if kind == "ctest" else " "
    return f"{kind}: {sep.join(items[:limit])} … (+{len(items) - limit})"


def kill_rate(rows):
    """caught / mutants that reached a verdict: timeouts, crashes and misses count against, build
    failures and stale mutants are left out."""
    judged = [r for r in rows if r["status"] in (DEVIATION, SOLVER, CRASH, TIMED_OUT, MISSED)]
    return sum(r["status"] in CAUGHT for r in judged), len(judged)


def summary_lines(rows):
    counts = ", ".join(f"{o} {sum(r['status'] == o for r in rows)}" for o in OUTCOMES)
    hand = [r for r in rows if r["kind"] != "random"]
    rnd = [r for r in rows if r["kind"] == "random"]
    groups = [("3%+", lambda s: s >= 3), ("2%", lambda s: 0 < s < 3), ("unsized", lambda s: s == 0)]
    parts = [f"{name} caught {'/'.join(map(str, kill_rate([r for r in hand if pred(float(r['size_pct']))])))}"
             for name, pred in groups]
    a, b = kill_rate(hand)
    c, d = kill_rate(rnd)
    return [f"outcomes: {counts}",
            f"hand-picked: caught {a}/{b} ({', '.join(parts)})",
            f"random: caught {c}/{d}"]


def write_results(rows, provenance, order, folder: Path):
    rows = sorted(rows, key=lambda r: order.index(r["id"]) if r["id"] in order else len(order))
    tsv = provenance + "\n" + "\t".join(RESULT_COLUMNS) + "\n"
    tsv += "".join("\t".join(str(r[c]).replace("\t", " ") for c in RESULT_COLUMNS) + "\n" for r in rows)
    md = [provenance.lstrip("# "), "",
          "| mutant | kind | size | what it models | result | stage | caught by / detail | s |",
          "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        size = f"{r['size_pct']}%" if float(r["size_pct"]) > 0 else "—"
        detail, models = fmt_caught_by(r["caught_by"]).replace("|", "\\|"), r["models"].replace("|", "\\|")
        md.append(f"| {r['id']} | {r['kind']} | {size} | {models} | {r['status']} | {r['stage']} | {detail} | {r['seconds']} |")
    md += [""] + [l + "  " for l in summary_lines(rows)[:-1]] + summary_lines(rows)[-1:]
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in (("results.tsv", tsv), ("results.md", "\n".join(md) + "\n")):
        tmp = folder / (name + ".tmp")
        tmp.write_text(text)
        tmp.replace(folder / name)
    return "\n".join(md)


def previous_rows(sha, folder: Path):
    """Rows of an earlier results.tsv of the same commit and columns, so a subset run adds to it."""
    p = folder / "results.tsv"
    if not p.is_file():
        return None
    lines = p.read_text().splitlines()
    if len(lines) < 2 or f"git {sha} " not in lines[0] + " " or lines[1].split("\t") != RESULT_COLUMNS:
        return None
    return {r["id"]: r for r in (dict(zip(RESULT_COLUMNS, l.split("\t"))) for l in lines[2:] if l)}


# ---------------------------------------------------------------------------------------------
# --check

def check(mutants):
    """--check: which mutants still apply to the working tree (no build); exit 1 if any is stale."""
    stale = 0
    for m in mutants:
        counts = [(ROOT / e["file"]).read_text().count(e["find"]) if (ROOT / e["file"]).is_file() else 0 for e in m["edits"]]
        ok = all(c == 1 for c in counts)
        stale += not ok
        print(f"{m['id']:<24} {'ok' if ok else 'STALE'} (found {counts})")
    print(f"{len(mutants) - stale}/{len(mutants)} mutants apply")
    return 1 if stale else 0


# ---------------------------------------------------------------------------------------------
# --generate-random N --seed S

RANDOM_DIRS = ("theory", "dsmc", "model", "compare")
RANDOM_BEGIN = "# --- random mutants"
RANDOM_END = "# --- end of random mutants ---"
FLOAT = re.compile(r"(?<![\w.'])((?:\d+\.\d*|\.\d+)(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+)([fFlL]?)(?![\w.'])")
COMPARISON = re.compile(r"(?<= )(<=|>=|<|>)(?= )")  # spaced, as the code's style writes them; not <<, ->, <=>
FLIP = {"<": "<=", "<=": "<", ">": ">=", ">=": ">"}


def code_mask(text: str):
    """One flag per character: True where it is code, False inside comments, string and character
    literals (raw strings included)."""
    mask = [True] * len(text)
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        start = i
        if text.startswith("//", i):
            i = text.find("\n", i)
            i = n if i < 0 else i
        elif text.startswith("/*", i):
            i = text.find("*/", i + 2)
            i = n if i < 0 else i + 2
        elif c == '"' and i > 0 and text[i - 1] == "R" and (i < 2 or not (text[i - 2].isalnum() or text[i - 2] == "_")):
            delim = text[i + 1:text.index("(", i)]
            i = text.find(")" + delim + '"', i)
            i = n if i < 0 else i + len(delim) + 2
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum())):
            i += 1
            while i < n and text[i] != c and text[i] != "\n":
                i += 2 if text[i] == "\\" else 1
            i += 1
        else:
            i += 1
            continue
        for k in range(start, min(i, n)):
            mask[k] = False
    return mask


def sites_in_text(text: str):
    """Candidate sites of one file: (line index, column, kind, token), kind 'constant' (a non-zero
    floating literal) or 'comparison'. Comments, strings, preprocessor lines and compile-time checks
    (static_assert, assert) are skipped."""
    mask = code_mask(text)
    sites, offset = [], 0
    for li, line in enumerate(text.split("\n")):
        code = "".join(ch if mask[offset + k] else " " for k, ch in enumerate(line))
        offset += len(line) + 1
        if code.lstrip().startswith("#") or re.search(r"\b(static_assert|assert)\s*\(", code):
            continue
        for mt in FLOAT.finditer(code):
            if float(mt.group(1)) != 0.0:
                sites.append((li, mt.start(), "constant", mt.group(0)))
        for mt in COMPARISON.finditer(code):
            if not re.search(r"\boperator\s*$", code[:mt.start()]):
                sites.append((li, mt.start(), "comparison", mt.group(1)))
    return sites


def source_files():
    """The .cpp/.hpp files of theory/, dsmc/, model/, compare/ (tracked ones in a checkout), sorted,
    without anything under a tests folder."""
    r = subprocess.run(["git", "-C", str(ROOT), "ls-files", *RANDOM_DIRS], capture_output=True, text=True)
    files = r.stdout.split() if r.returncode == 0 else \
        [str(p.relative_to(ROOT)) for d in RANDOM_DIRS for p in (ROOT / d).rglob("*")]
    return sorted(f for f in files if f.endswith((".cpp", ".hpp")) and "tests" not in Path(f).parts)


def unique_find(text: str, lines, li: int, col: int):
    """The shortest run of whole lines around line li that occurs once in text, and the site's offset in it."""
    for before in range(0, 3):
        for after in range(0, 4):
            a, b = li - before, li + after
            if a < 0 or b >= len(lines):
                continue
            find = "\n".join(lines[a:b + 1])
            if find.strip() and text.count(find) == 1:
                return find, sum(len(lines[k]) + 1 for k in range(a, li)) + col
    return None, None


def draw_random(n: int, seed: int, root: Path | None = None):
    """n random mutants with seed: a kind (constant or comparison, even odds), a file that has sites of
    that kind (uniformly, so that the long coefficient tables do not take most draws), then a site in
    it (uniformly); a constant is scaled by 1.02 or 1.03, a comparison flipped (< and <=, > and >=).
    Deterministic for a given seed and tree."""
    root = root or ROOT
    rng = random.Random(seed)
    by_kind = {"constant": {}, "comparison": {}}  # kind -> file -> sites
    texts = {}
    for f in source_files() if root == ROOT else sorted(str(p.relative_to(root)) for p in root.rglob("*.?pp")):
        texts[f] = (root / f).read_text()
        for li, col, kind, tok in sites_in_text(texts[f]):
            by_kind[kind].setdefault(f, []).append((li, col, tok))
    chosen, used = [], set()
    while len(chosen) < n and any(by_kind.values()):
        kind = rng.choice([k for k in sorted(by_kind) if by_kind[k]])
        f = rng.choice(sorted(by_kind[kind]))
        li, col, tok = by_kind[kind][f].pop(rng.randrange(len(by_kind[kind][f])))
        if not by_kind[kind][f]:
            del by_kind[kind][f]
        factor = rng.choice(["1.02", "1.03"]) if kind == "constant" else None
        lines = texts[f].split("\n")
        find, at = unique_find(texts[f], lines, li, col)
        if find is None or (f, li) in used:
            continue
        used.add((f, li))
        if kind == "constant":
            new, size = f"({tok} * {factor})", int(round((float(factor) - 1) * 100))
            models = f"random: the constant {tok} × {factor} ({f} line {li + 1})"
        else:
            new, size = FLIP[tok], 0
            models = f"random: `{tok}` → `{new}` ({f} line {li + 1})"
        replace = find[:at] + new + find[at + len(tok):]
        chosen.append({"id": f"rand-{seed}-{len(chosen) + 1:02d}", "size": size, "models": models,
                       "file": f, "find": find, "replace": replace})
    return chosen


def toml_str(s: str):
    return json.dumps(s, ensure_ascii=False)  # a JSON string is a TOML basic string


def random_section(mutants, n, seed):
    out = [f"{RANDOM_BEGIN}: `run_mutants.py --generate-random {n} --seed {seed}` drew these; regenerate, do not edit ---",
           "# size: the relative change of the constant (0 for a flipped comparison), not of a computed quantity."]
    for m in mutants:
        out += ["", "[[mutant]]", f"id = {toml_str(m['id'])}", "random = true", f"seed = {seed}", f"size = {m['size']}",
                f"models = {toml_str(m['models'])}", f"file = {toml_str(m['file'])}",
                f"find = {toml_str(m['find'])}", f"replace = {toml_str(m['replace'])}"]
    return "\n".join(out + ["", RANDOM_END, ""])


def generate_random(n, seed):
    path = HERE / "mutants.toml"
    text = path.read_text()
    begin, end = text.find(RANDOM_BEGIN), text.find(RANDOM_END)
    if begin >= 0 and end > begin:
        text = text[:begin] + text[end + len(RANDOM_END):].lstrip("\n")
    text = text.rstrip("\n") + "\n\n" + random_section(draw_random(n, seed), n, seed)
    tmp = path.with_suffix(".toml.tmp")
    tmp.write_text(text)
    all_mutants(tmp)  # parses, ids unique
    tmp.replace(path)
    return check([m for m in all_mutants() if m["kind"] == "random"])


# ---------------------------------------------------------------------------------------------
# --self-test: the classification on stub stages, no build, no git

def self_test():
    global TIMEOUT
    py = sys.executable
    ok = [0, 0]

    def expect(name, got, want):
        ok[0] += got == want
        ok[1] += 1
        print(f"{'ok  ' if got == want else 'FAIL'} {name}: {got!r}" + ("" if got == want else f", expected {want!r}"))

    def sh(script):
        return ["sh", "-c", script]

    with tempfile.TemporaryDirectory(prefix="granmix-mutants-selftest-") as tmp:
        tmp = Path(tmp)
        logs, out_dir = tmp / "logs", tmp / "out"
        logs.mkdir()
        out_dir.mkdir()
        saved, TIMEOUT = TIMEOUT, 1.5
        passing = sh("exit 0")
        failing_row = sh(f"printf 'scene\\tquantity\\tpass\\ns\\tT\\t0\\ns\\tmsd\\t1\\n' > {out_dir}/summary.tsv; exit 1")
        error_only = sh(f"printf 'scene\\tquantity\\tpass\\n' > {out_dir}/summary.tsv; "
                        f"echo '{{\"errors\": [\"s.toml: solver gave up\"]}}' > {out_dir}/summary.json; exit 1")
        ctest_out = "The following tests FAILED:\n\t  7 - model: a test ({})\n\t  9 - theory: b ({})\nErrors while running CTest\n"
        cases = [
            # name, build, validate, build-tests, ctest, expected (outcome, stage)
            ("a do-nothing mutant: every stage exits 0", passing, passing, passing, passing, (MISSED, "")),
            ("validate exit 1 with a failing row", passing, failing_row, passing, passing, (DEVIATION, "validate")),
            ("validate exit 1, only a scene that stopped", passing, error_only, passing, passing, (SOLVER, "validate")),
            ("validate exit 3", passing, sh("echo 'granmix: numerical failure: energy balance' >&2; exit 3"), passing,
             passing, (SOLVER, "validate")),
            ("validate exit 2", passing, sh("exit 2"), passing, passing, (CRASH, "validate")),
            ("validate killed by SIGSEGV", passing, sh("kill -SEGV $$"), passing, passing, (CRASH, "validate")),
            ("validate sleeps beyond the timeout", passing, sh("sleep 30"), passing, passing, (TIMED_OUT, "validate")),
            ("granmix does not compile", sh("exit 1"), passing, passing, passing, (BUILD_FAILED, "build")),
            ("the build runs out of time", sh("sleep 30"), passing, passing, passing, (TIMED_OUT, "build")),
            ("the tests do not compile", passing, passing, sh("exit 2"), passing, (BUILD_FAILED, "build-tests")),
            ("a ctest test fails", passing, passing, passing, sh(f"printf '{ctest_out.format('Failed', 'Timeout')}'; exit 8"),
             (DEVIATION, "ctest")),
            ("a ctest test only times out", passing, passing, passing,
             sh(f"printf '{ctest_out.format('Timeout', 'Timeout')}'; exit 8"), (TIMED_OUT, "ctest")),
            ("a ctest test crashes", passing, passing, passing,
             sh(f"printf '{ctest_out.format('SEGFAULT', 'Timeout')}'; exit 8"), (CRASH, "ctest")),
            ("ctest sleeps beyond the timeout", passing, passing, passing, sh("sleep 30"), (TIMED_OUT, "ctest")),
            ("only a test that fails on the unmutated tree fails", passing, passing, passing,
             sh(f"printf '{ctest_out.format('Failed', 'Failed').replace(chr(10) + chr(9) + '  9 - theory: b (Failed)', '')}'; exit 8"),
             (MISSED, "")),
        ]
        rows = []
        for name, b, v, bt, ct, want in cases:
            for f in out_dir.iterdir():
                f.unlink()
            start = time.monotonic()
            baseline = frozenset({"model: a test"}) if "unmutated" in name else frozenset()
            status, stage, detail = run_stages([b], v, [bt], ct, logs, "stub", out_dir, baseline=baseline)
            expect(name, (status, stage), want)
            rows.append({"id": f"stub-{len(rows) + 1}", "kind": "random" if len(rows) % 2 else "hand", "size_pct": 3,
                         "status": status, "stage": stage, "caught_by": detail,
                         "seconds": round(time.monotonic() - start), "files": "-", "models": name})
        expect("the failing row is named", rows[1]["caught_by"], "validate: s:T")
        # The confirmation: a first failure counts only when a scene fails again, cheapest scene first.
        confirm_dir = tmp / "confirm"
        confirm_dir.mkdir()
        two_rows = sh(f"printf 'scene\\tquantity\\tpass\\tdsmc_seconds\\nbig\\tT\\t0\\t9\\nsmall\\tT\\t0\\t1\\n' > {out_dir}/summary.tsv; exit 1")
        tried = []

        def confirm_with(repeats):
            def confirm(scene):
                tried.append(scene)
                d = confirm_dir / scene
                d.mkdir(exist_ok=True)
                fails = sh(f"printf 'scene\\tquantity\\tpass\\tverdict\\n{scene}\\tT\\t0\\tFAIL\\n' > {d}/summary.tsv; exit 1")
                return (fails if scene in repeats else passing), d
            return confirm

        for f in out_dir.iterdir():
            f.unlink()
        got = run_stages([passing], two_rows, [passing], passing, logs, "stub", out_dir, confirm=confirm_with({"big"}))
        expect("a failure confirmed in the second scene tried: caught, cheapest tried first",
               (got[0], got[1], got[2], tried), (DEVIATION, "validate", "validate (confirmed): big:T", ["small", "big"]))
        tried.clear()
        got = run_stages([passing], two_rows, [passing], passing, logs, "stub", out_dir, confirm=confirm_with(set()))
        expect("no failure confirmed: validate counts as passed, the mutant is missed and says why",
               got, (MISSED, "", "validate failed at seed 1, none confirmed: small big"))
        expect("the stopped scene is named", rows[2]["caught_by"], "validate: s:ERROR (solver gave up)")
        expect("a failing ctest test is named, its timeouts noted",
               classify_ctest(8, ctest_out.format("Failed", "Timeout"))[1], "ctest: model: a test [timeout: theory: b]")
        expect("a test failing on the unmutated tree is not counted, another one is",
               classify_ctest(8, ctest_out.format("Failed", "Failed"), frozenset({"model: a test"}))[1], "ctest: theory: b")
        # A timed-out stage leaves no process behind (its whole session is killed).
        pidfile = tmp / "pid"
        rc, _ = run(sh(f"sleep 30 & echo $! > {pidfile}; wait"), logs / "orphan.log", timeout=1)
        time.sleep(0.2)
        child = int(pidfile.read_text())
        try:
            os.kill(child, 0)
            alive = Path(f"/proc/{child}/stat").read_text().split()[2] != "Z"
        except (ProcessLookupError, FileNotFoundError):
            alive = False
        expect("a timed-out stage's child process is killed", (rc, alive), (None, False))
        TIMEOUT = saved
        # The counts: only the two caught outcomes are caught; timeouts and crashes count against the kill
        # rate, build failures are left out of it.
        md = write_results(rows, f"# granmix mutants: git {'a' * 40} date - self-test (stub stages)", [r["id"] for r in rows],
                           tmp / "results")
        expect("kill rate over the stub mutants", kill_rate(rows), (4, 13))
        expect("the table reports the misses", "| missed |" in md and f"{MISSED} 2," in md, True)
        expect("hand-picked and random rates apart",
               [l.split(":")[0] for l in summary_lines(rows)], ["outcomes", "hand-picked", "random"])
        expect("one commit per table: a subset of the same commit adds to it, of another commit does not",
               (len(previous_rows("a" * 40, tmp / "results") or {}), previous_rows("b" * 40, tmp / "results")), (len(rows), None))

    # The random sites: comments, strings, preprocessor lines and asserts are skipped; zero is never scaled.
    fixture = "\n".join([
        "// 0.5 < 1 in a comment",
        'const char* s = "0.25 < x";  /* 1.5 > 2 */',
        "double a = 0.75 * b, c = 0.0;",
        "if (x < y) f(2.5e-3, 1'000, 'a');",
        "std::vector<double> v; x << 1; p->q; auto r = a <=> b;",
        "#include <a>",
        "static_assert(1.0 < 2.0);",
        "bool operator < (const A&) const; while (k >= 1e3f) {}",
        'auto h = R"(<b> 3.5 < 4)";',
    ])
    expect("random sites of a fixture", [(li, kind, tok) for li, _, kind, tok in sites_in_text(fixture)],
           [(2, "constant", "0.75"), (3, "constant", "2.5e-3"), (3, "comparison", "<"), (7, "constant", "1e3f"),
            (7, "comparison", ">=")])
    with tempfile.TemporaryDirectory(prefix="granmix-mutants-selftest-") as tmp:
        (Path(tmp) / "a.cpp").write_text(fixture + "\nint g(double y) { return y > 0.125 ? 1 : 2; }\n")
        first, again = draw_random(4, 7, Path(tmp)), draw_random(4, 7, Path(tmp))
        expect("the same seed draws the same mutants", first == again and len(first) == 4, True)
        text = (Path(tmp) / "a.cpp").read_text()
        expect("every drawn mutant applies once and changes the text",
               all(text.count(m["find"]) == 1 and m["find"] != m["replace"] for m in first), True)
    print(f"self-test: {ok[0]}/{ok[1]} checks pass")
    return 0 if ok[0] == ok[1] else 1


# ---------------------------------------------------------------------------------------------

def main():
    args = sys.argv[1:]
    if "--self-test" in args:
        sys.exit(self_test())
    if "--generate-random" in args:
        try:
            n = int(args[args.index("--generate-random") + 1])
            seed = int(args[args.index("--seed") + 1])
        except (IndexError, ValueError):
            sys.exit("usage: run_mutants.py --generate-random N --seed S")
        sys.exit(generate_random(n, seed))
    mutants, subset = load_mutants()
    if "--check" in args:
        sys.exit(check(mutants))
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # as SIGINT: kill the stage, restore the files
    order = [m["id"] for m in all_mutants()]
    sha = git("rev-parse", REV)
    if REV == "HEAD" and git("status", "--porcelain", "--untracked-files=no"):
        print(f"mutants: note: uncommitted changes are not tested (scratch = git archive {sha[:10]})", flush=True)
    key = hashlib.sha1(str(ROOT).encode()).hexdigest()[:8]
    scratch = Path(os.environ.get("MUTANTS_SCRATCH") or Path(tempfile.gettempdir()) / f"granmix-mutants-{key}")
    src, bld, logs = scratch / "src", scratch / "build", scratch / "logs"
    logs.mkdir(parents=True, exist_ok=True)
    # One table, one commit: a subset adds to a table of the same commit; otherwise it gets a table of its own.
    folder = Path(os.environ.get("MUTANTS_RESULTS") or HERE)
    rows = previous_rows(sha, folder) if subset else {}
    if rows is None:
        folder, rows = scratch / "results", previous_rows(sha, scratch / "results") or {}
        print(f"mutants: {HERE / 'results.tsv'} is not a table of {sha[:10]}: this subset's table goes to {folder}", flush=True)
    print(f"mutants: {len(mutants)} mutants, scratch {scratch}, JOBS={JOBS}", flush=True)
    sync_scratch(src)
    r = stage_build(build_cmds(src, bld, "granmix"), logs / "pristine.build.log", "granmix")
    if r:
        sys.exit(f"mutants: the unmutated tree does not build ({r[0]}; see {logs / 'pristine.build.log'})")
    baseline = baseline_failures(src, bld, logs)
    if baseline:
        print(f"mutants: {len(baseline)} tests fail on the unmutated tree and are not counted: {' | '.join(sorted(baseline))}",
              flush=True)
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    provenance = (f"# granmix mutants: git {sha} date {date} validate --fidelity quick, then ctest -LE {SCRATCH_EXCLUDED_LABEL}"
                  + (f"; not counted, failing unmutated: {' | '.join(sorted(baseline))}" if baseline else ""))
    for i, m in enumerate(mutants, 1):
        start = time.monotonic()
        status, stage, caught_by = run_mutant(m, src, bld, logs, baseline)
        files = ",".join(dict.fromkeys(e["file"] for e in m["edits"]))
        rows[m["id"]] = {"id": m["id"], "kind": m["kind"], "size_pct": m["size"], "status": status, "stage": stage,
                         "caught_by": caught_by, "seconds": round(time.monotonic() - start), "files": files,
                         "models": m["models"]}
        print(f"[{i}/{len(mutants)}] {m['id']:<24} {status:<20} {rows[m['id']]['seconds']:>5} s  {fmt_caught_by(caught_by)}",
              flush=True)
        write_results(list(rows.values()), provenance, order, folder)
    print(write_results(list(rows.values()), provenance, order, folder))


if __name__ == "__main__":
    main()
