#!/usr/bin/env python3
"""Mutation harness: how many plausible physics bugs does the suite catch? (issue 11, item 5)

Each mutant of mutants.toml is a few exact text edits applied to a scratch copy of the committed
tree (git archive of HEAD or MUTANTS_REV, kept between runs so rebuilds are incremental; the real
tree is never edited). Per mutant: apply, build granmix, `granmix validate --fidelity quick`
(caught if exit != 0), and only if validate passes, build the tests and run ctest (caught if a test
fails); then the files are restored. A mutant whose search text is not found exactly once is
`stale`, never skipped silently.

Environment: MUTANTS=id1,id2 (a subset, run in that order), JOBS (build, ctest and validate
threads; default 2), MUTANTS_REV (the commit to mutate; default HEAD), MUTANTS_SCRATCH (scratch
folder), MUTANTS_TIMEOUT (seconds per step, default 3600). `--check` only tells which mutants
still apply to the working tree. Writes tests/mutants/results.tsv and results.md (a subset run
adds to an earlier result of the same commit) and prints the kill table.
Python 3.11 standard library only (tomllib).
"""
import datetime
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = Path(subprocess.run(["git", "-C", str(HERE), "rev-parse", "--show-toplevel"], check=True,
                           capture_output=True, text=True).stdout.strip())
JOBS = int(os.environ.get("JOBS") or 2)
TIMEOUT = float(os.environ.get("MUTANTS_TIMEOUT") or 3600)
REV = os.environ.get("MUTANTS_REV") or "HEAD"
RESULT_COLUMNS = ["id", "size_pct", "status", "caught_by", "seconds", "files", "models"]


def git(*args):
    return subprocess.run(["git", "-C", str(ROOT), *args], check=True, capture_output=True, text=True).stdout.strip()


def load_mutants():
    with open(HERE / "mutants.toml", "rb") as f:
        mutants = tomllib.load(f)["mutant"]
    for m in mutants:
        m["edits"] = [{"file": m["file"], "find": m["find"], "replace": m["replace"]}] + m.get("edit", [])
    ids = [m["id"] for m in mutants]
    if len(set(ids)) != len(ids):
        sys.exit("mutants.toml: duplicate ids")
    wanted = [s.strip() for s in os.environ.get("MUTANTS", "").split(",") if s.strip()]
    if not wanted:
        return mutants
    unknown = [w for w in wanted if w not in ids]
    if unknown:
        sys.exit(f"MUTANTS: unknown id(s) {', '.join(unknown)} (allowed: {', '.join(ids)})")
    return [next(m for m in mutants if m["id"] == w) for w in wanted]


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


def run(cmd, log: Path, cwd=None, tmp: Path | None = None):
    """Run cmd, output to log; returns (exit code or None on timeout, output). With tmp, the command's
    TMPDIR is that fresh folder: the tests' fixed /tmp/granmix-test-* folders would otherwise be
    shared with any other checkout running its tests at the same time (a false `caught`)."""
    env = None
    if tmp is not None:
        shutil.rmtree(tmp, ignore_errors=True)
        tmp.mkdir(parents=True)
        env = dict(os.environ, TMPDIR=str(tmp))
    try:
        r = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT)
        out, rc = r.stdout, r.returncode
    except subprocess.TimeoutExpired as e:  # its output arrives as bytes even with text=True
        out, rc = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or ""), None
    log.write_text(out)
    return rc, out


def build(src: Path, bld: Path, log: Path, target=None):
    """Configure and build (one target, or everything: the tests are built only when validate has
    not caught the mutant, which saves recompiling every test that includes a mutated header)."""
    configure = ["cmake", "-S", str(src), "-B", str(bld), "-DCMAKE_BUILD_TYPE=Release"]
    if shutil.which("ccache"):
        configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    rc, out = run(configure, log)
    if rc == 0:
        rc, out2 = run(["cmake", "--build", str(bld), f"-j{JOBS}"] + (["--target", target] if target else []), log)
        out += out2
        log.write_text(out)
    return rc == 0


def validate_failures(out_dir: Path):
    """Failing scene:quantity rows of summary.tsv and the scene errors of summary.json."""
    failed = []
    tsv = out_dir / "summary.tsv"
    if tsv.is_file():
        lines = [l for l in tsv.read_text().splitlines() if l and not l.startswith("#")]
        head = lines[0].split("\t")
        for l in lines[1:]:
            row = dict(zip(head, l.split("\t")))
            if row.get("pass") == "0":
                failed.append(f"{row['scene']}:{row['quantity']}" if row["quantity"] != "-" else row["scene"])
    js = out_dir / "summary.json"
    if js.is_file():
        failed += [f"{e.split(':')[0].removesuffix('.toml')}:ERROR" for e in json.loads(js.read_text()).get("errors", [])]
    return failed


def ctest_failures(out: str):
    failed, on = [], False
    for line in out.splitlines():
        if "The following tests FAILED" in line:
            on = True
        elif on and " - " in line:
            failed.append(line.split(" - ", 1)[1].rsplit(" (", 1)[0].strip())
    return failed


def run_mutant(m, src: Path, bld: Path, logs: Path):
    # All edits are checked on the texts in memory first: a stale mutant leaves the tree untouched.
    originals, mutated = {}, {}
    for e in m["edits"]:
        path = src / e["file"]
        if e["file"] not in mutated:
            if not path.is_file():
                return "stale", f"{e['file']}: no such file"
            originals[e["file"]] = mutated[e["file"]] = path.read_text()
        n = mutated[e["file"]].count(e["find"])
        if n != 1:
            return "stale", f"{e['file']}: search text found {n} times: {e['find']}"
        mutated[e["file"]] = mutated[e["file"]].replace(e["find"], e["replace"])
    for f, t in mutated.items():
        (src / f).write_text(t)
    try:
        if not build(src, bld, logs / f"{m['id']}.build.log", "granmix"):
            return "build-failed", f"see {logs / (m['id'] + '.build.log')}"
        with tempfile.TemporaryDirectory(prefix="granmix-mutant-") as out_dir:
            rc, out = run([str(bld / "granmix"), "validate", "--fidelity", "quick", "--out", out_dir, "--threads", str(JOBS),
                           "--scenes", str(src / "compare" / "scenes")], logs / f"{m['id']}.validate.log", cwd=src)
            if rc != 0:
                # No failing row: the run stopped before comparing (a solver failure names itself).
                stopped = [l.split(": ", 1)[1][:200] for l in out.splitlines() if l.startswith("granmix: ")][:1]
                if stopped and not validate_failures(Path(out_dir)):
                    return "caught", "validate stopped: " + stopped[0]
                why = validate_failures(Path(out_dir)) or ["(no failing row)"]
                note = "timeout" if rc is None else ("" if rc == 1 else f"exit {rc}")
                return "caught", "validate: " + " ".join(why) + (f" [{note}]" if note else "")
        if not build(src, bld, logs / f"{m['id']}.build-tests.log"):
            return "build-failed", f"tests: see {logs / (m['id'] + '.build-tests.log')}"
        rc, out = run(["ctest", "-j", str(JOBS)], logs / f"{m['id']}.ctest.log", cwd=bld, tmp=bld.parent / "tmp")
        if rc != 0:
            return "caught", "ctest: " + (" | ".join(ctest_failures(out)) or ("timeout" if rc is None else f"exit {rc}"))
        return "missed", ""
    finally:
        for f, t in originals.items():
            (src / f).write_text(t)


def fmt_caught_by(s, limit=4):
    kind, _, rest = s.partition(": ")
    if kind == "validate stopped":  # one message, not a list of rows
        return s
    items = rest.split(" | ") if kind == "ctest" else rest.split(" ")
    if len(items) <= limit:
        return s
    return f"{kind}: {' '.join(items[:limit]) if kind != 'ctest' else ' | '.join(items[:limit])} … (+{len(items) - limit})"


def summary_line(rows):
    def count(pred):
        sel = [r for r in rows if r["status"] != "stale" and pred(float(r["size_pct"]))]
        return sum(r["status"] == "caught" for r in sel), len(sel)
    a, b = count(lambda s: s >= 3)
    c, d = count(lambda s: 0 < s < 3)
    e, f = count(lambda s: s == 0)
    stale = sum(r["status"] == "stale" for r in rows)
    failed = sum(r["status"] == "build-failed" for r in rows)
    return f"3%+ caught {a}/{b}, 2% caught {c}/{d}, unsized caught {e}/{f}; stale {stale}, build-failed {failed}"


def write_results(rows, provenance, order):
    rows = sorted(rows, key=lambda r: order.index(r["id"]) if r["id"] in order else len(order))
    tsv = provenance + "\n" + "\t".join(RESULT_COLUMNS) + "\n"
    tsv += "".join("\t".join(str(r[c]).replace("\t", " ") for c in RESULT_COLUMNS) + "\n" for r in rows)
    md = [provenance.lstrip("# "), "", "| mutant | size | what it models | result | caught by | s |", "|---|---|---|---|---|---|"]
    for r in rows:
        size = f"{r['size_pct']}%" if float(r["size_pct"]) > 0 else "—"
        md.append(f"| {r['id']} | {size} | {r['models']} | {r['status']} | {fmt_caught_by(r['caught_by'])} | {r['seconds']} |")
    md += ["", summary_line(rows)]
    for name, text in (("results.tsv", tsv), ("results.md", "\n".join(md) + "\n")):
        tmp = HERE / (name + ".tmp")
        tmp.write_text(text)
        tmp.replace(HERE / name)
    return "\n".join(md)


def previous_rows(sha):
    """Rows of an earlier results.tsv of the same commit, so a subset run adds to it."""
    p = HERE / "results.tsv"
    if not p.is_file():
        return {}
    lines = p.read_text().splitlines()
    if not lines or f"git {sha}" not in lines[0]:
        return {}
    return {r["id"]: r for r in (dict(zip(RESULT_COLUMNS, l.split("\t"))) for l in lines[2:] if l)}


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


def main():
    mutants = load_mutants()
    if "--check" in sys.argv[1:]:
        sys.exit(check(mutants))
    with open(HERE / "mutants.toml", "rb") as f:
        order = [m["id"] for m in tomllib.load(f)["mutant"]]
    sha = git("rev-parse", REV)
    if REV == "HEAD" and git("status", "--porcelain", "--untracked-files=no"):
        print(f"mutants: note: uncommitted changes are not tested (scratch = git archive {sha[:10]})", flush=True)
    key = hashlib.sha1(str(ROOT).encode()).hexdigest()[:8]
    scratch = Path(os.environ.get("MUTANTS_SCRATCH") or Path(tempfile.gettempdir()) / f"granmix-mutants-{key}")
    src, bld, logs = scratch / "src", scratch / "build", scratch / "logs"
    logs.mkdir(parents=True, exist_ok=True)
    print(f"mutants: {len(mutants)} mutants, scratch {scratch}, JOBS={JOBS}", flush=True)
    sync_scratch(src)
    if not build(src, bld, logs / "pristine.build.log", "granmix"):
        sys.exit(f"mutants: the unmutated tree does not build (see {logs / 'pristine.build.log'})")
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    provenance = f"# granmix mutants: git {sha} date {date} validate --fidelity quick, then ctest"
    rows = previous_rows(sha)
    for i, m in enumerate(mutants, 1):
        start = time.monotonic()
        status, caught_by = run_mutant(m, src, bld, logs)
        files = ",".join(dict.fromkeys(e["file"] for e in m["edits"]))
        rows[m["id"]] = {"id": m["id"], "size_pct": m["size"], "status": status, "caught_by": caught_by,
                         "seconds": round(time.monotonic() - start), "files": files, "models": m["models"]}
        print(f"[{i}/{len(mutants)}] {m['id']:<24} {status:<12} {rows[m['id']]['seconds']:>5} s  {fmt_caught_by(caught_by)}", flush=True)
        write_results(list(rows.values()), provenance, order)
    print(write_results(list(rows.values()), provenance, order))


if __name__ == "__main__":
    main()
