"""The Python module granmix (python/, docs/python.md) against the command line it shares its code with.

Run by ctest (label python) with PYTHONPATH = the build's python folder and GRANMIX_EXE = the granmix executable; skipped
as a whole when the module has not been built. Numbers are compared exactly: the binding's doubles against the
command line's JSON and TSV text (shortest round-trip form, so float() gives back the very double)."""
import importlib.util
import json
import os
import pathlib
import signal
import statistics
import subprocess
import sys
import threading
import time
import tomllib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / 'compare' / 'scenes'
EXAMPLES = ROOT / 'examples' / 'python'

_spec = importlib.util.find_spec('granmix')
if _spec is None or not any(pathlib.Path(p).glob('_core*.so') for p in _spec.submodule_search_locations or []):
    pytest.skip('the module granmix is not built (GRANMIX_PYTHON=OFF, or PYTHONPATH lacks build/python)', allow_module_level=True)

import numpy as np  # noqa: E402

import granmix  # noqa: E402

EXE = os.environ.get('GRANMIX_EXE') or str(pathlib.Path(granmix.__file__).resolve().parents[2] / 'granmix')

# A small binary with DSMC and two compared quantities: fractions of a second at quick fidelity.
TINY = {
    'scene': {'name': 'py-tiny', 'source': 'test', 'title': 'binary, eps = 0.8'},
    'mixture': {'species': [{'mass': 1, 'diameter': 1, 'density': 0.1}, {'mass': 4, 'diameter': 1.5, 'density': 0.05}]},
    'collisions': {'restitution': 0.8},
    'time': {'start': 0.1, 'end': 20.0, 'points': 6, 'spacing': 'log'},
    'observables': {'temperatures': True, 'msd': True},
    'dsmc': {'quick': {'particles': 2000, 'replicas': 4}, 'paper': {'particles': 4000, 'replicas': 4}},
    'compare': {'quantities': [{'name': 'T', 'relative': 0.05, 'z': 4, 'why': 'test'},
                               {'name': 'msd', 'species': [1, 2], 'relative': 0.05, 'z': 4, 'why': 'test'}]},
}


def run_cli(*args, check=True):
    r = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True, env=dict(os.environ, OMP_WAIT_POLICY='passive'))
    if check and r.returncode != 0:
        raise AssertionError(f'granmix {" ".join(map(str, args))}: exit {r.returncode}\n{r.stderr}')
    return r


def cli_message(r):
    """The one error line of the command line, without its prefix."""
    line = r.stderr.strip()
    assert line.count('\n') == 0, r.stderr
    for prefix in ('granmix: numerical failure: ', 'granmix: '):
        if line.startswith(prefix):
            return line[len(prefix):]
    return line


def read_tsv(path):
    """columns, {column: float64 array} of a granmix TSV file (provenance lines skipped)."""
    lines = [l for l in pathlib.Path(path).read_text().splitlines() if l and not l.startswith('#')]
    columns = lines[0].split('\t')
    rows = [[float(x) for x in l.split('\t')] for l in lines[1:]]
    data = np.array(rows, dtype=np.float64).reshape(len(rows), len(columns))
    return columns, {c: data[:, i] for i, c in enumerate(columns)}


def assert_same_table(result, path):
    columns, data = read_tsv(path)
    assert result.columns == columns
    for c in columns:
        a, b = result[c], data[c]
        # exact: the same doubles bit for bit (NaN where a column does not apply, in the same rows)
        assert np.array_equal(np.isnan(a), np.isnan(b)), c
        assert np.array_equal(a[~np.isnan(a)].view(np.uint64), b[~np.isnan(b)].view(np.uint64)), c


@pytest.fixture(scope='module')
def tiny_file(tmp_path_factory):
    path = tmp_path_factory.mktemp('scene') / 'py-tiny.toml'
    path.write_text(granmix.Scene.from_dict(TINY).to_toml())
    return path


# ---------------------------------------------------------------------------------------------- hcs

HCS_CASES = [
    {'mass': [1.0, 100.0], 'diameter': [1.0, 4.641588833612779], 'density': [0.1, 0.1], 'eps': 0.5},
    {'mass': [1.0, 2.0, 5.0], 'diameter': [1.0, 1.2, 1.7], 'density': [0.1, 0.05, 0.02], 'eps': 0.7, 'nstar': 0.2},
    {'mass': [1.0], 'diameter': [1.0], 'density': [0.1], 'eps': 0.9},
    {'mu': 2.0, 'delta': 1.0, 'w': 1.0, 'alpha': 0.8},
    {'mu': 0.5, 'delta': 2.0, 'w': 1.2, 'alpha11': 0.9, 'alpha22': 0.7, 'alpha12': 0.8, 'nstar': 0.1},
    {'mass': [1.0, 4.0], 'diameter': [1.0, 1.0], 'density': [0.1, 0.1], 'eps': 0.8, 'converged': True},
    {'mass': [1.0, 1000.0], 'diameter': [1.0, 10.0], 'density': [0.1, 1e-4], 'eps': 0.5},
]


def hcs_flags(kw):
    flags = []
    for k, v in kw.items():
        if isinstance(v, bool):
            flags += [f'--{k}'] if v else []
        elif isinstance(v, list):
            flags += [f'--{k}', ','.join(repr(x) for x in v)]
        else:
            flags += [f'--{k}', repr(v)]
    return flags


def same_json(a, b, where='hcs'):
    """Equal keys in the same order, equal types and bit-equal floats."""
    assert type(a) is type(b), f'{where}: {type(a).__name__} != {type(b).__name__}'
    if isinstance(a, dict):
        assert list(a) == list(b), where
        for k in a:
            same_json(a[k], b[k], f'{where}.{k}')
    elif isinstance(a, list):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            same_json(x, y, f'{where}[{i}]')
    elif isinstance(a, float):
        assert a.hex() == b.hex(), f'{where}: {a!r} != {b!r}'
    else:
        assert a == b, where


@pytest.mark.parametrize('kw', HCS_CASES, ids=lambda kw: ','.join(kw))
def test_hcs_equals_the_command_line_json(kw):
    cli = json.loads(run_cli('hcs', '--json', *hcs_flags(kw)).stdout)
    same_json(granmix.hcs(**kw), cli)


def test_hcs_errors_are_scene_errors_with_the_command_lines_message():
    cases = [{'mass': [1.0, 2.0], 'diameter': [1.0, 1.0], 'density': [0.1, 0.1], 'eps': 1.5},
             {'mass': [1.0, 2.0], 'diameter': [1.0], 'density': [0.1, 0.1], 'eps': 0.5},
             {'mass': [1.0, -2.0], 'diameter': [1.0, 1.0], 'density': [0.1, 0.1], 'eps': 0.5},
             {'eps': 0.5},
             {'mass': [1.0, 2.0], 'diameter': [1.0, 1.0], 'density': [0.1, 0.1], 'eps': 0.5, 'mu': 2.0},
             {'mu': 2.0, 'delta': 1.0, 'w': 1.0, 'alpha': 0.8, 'alpha12': 0.5},
             {'mass': [1.0, 2.0], 'diameter': [1.0, 1.0], 'density': [0.1, 0.1], 'eps': 0.5, 'nstar': 2.0},
             {'mass': [1.0, 2.0], 'diameter': [1.0, 1.0], 'density': [0.1, 0.1]},
             {'mu': 2.0, 'delta': 1.0, 'w': 1.0}]
    for kw in cases:
        with pytest.raises(granmix.SceneError) as e:
            granmix.hcs(**kw)
        r = run_cli('hcs', '--json', *hcs_flags(kw), check=False)
        assert r.returncode == 2
        assert str(e.value) == cli_message(r)
        assert isinstance(e.value, ValueError)


def test_hcs_warnings_inputs_and_version_are_in_the_dict():
    """Masses 1:1000 of one material: c1 = 1.69 at first Sonine, 0.54 at order 3 (docs/user-guide.md, warnings)."""
    h = granmix.hcs(mass=[1.0, 1000.0], diameter=[1.0, 10.0], density=[0.1, 1e-4], eps=0.5)
    codes = {(w['code'], w.get('species')) for w in h['warnings']}
    assert {('c_large', 1), ('c_orders_disagree', 1), ('T_ratio_orders_disagree', 2)} <= codes
    assert all('--converged' in w['message'] for w in h['warnings'])
    assert h['inputs'] == {'mass': [1.0, 1000.0], 'diameter': [1.0, 10.0], 'density': [0.1, 1e-4], 'eps': 0.5, 'nstar': 0.0,
                           'converged': False}
    assert (h['version'], h['git_sha']) == (granmix.__version__, granmix._core.git_sha)
    assert granmix.hcs(mu=10.0, delta=2.0, w=1.0, alpha=0.5)['warnings'] == []  # MG Fig. 1's mixture


def test_hcs_refuses_positional_unknown_and_mistyped_arguments():
    with pytest.raises(TypeError):
        granmix.hcs([1.0, 2.0], [1.0, 1.0], [0.1, 0.1], 0.5)  # keywords only
    with pytest.raises(TypeError):
        granmix.hcs(mass=[1.0, 2.0], diameter=[1.0, 1.0], density=[0.1, 0.1], epsilon=0.5)
    with pytest.raises(TypeError):
        granmix.hcs(mass='heavy', diameter=[1.0], density=[0.1], eps=0.5)


def test_hcs_call_overhead_for_a_binary():
    """Prints the binding's cost beyond the C++ computation, call by call (median); no assertion on time."""
    kw = {'mass': [1.0, 2.0], 'diameter': [1.0, 1.0], 'density': [0.1, 0.1], 'eps': 0.8}
    granmix.hcs(**kw)
    totals, overheads = [], []
    for _ in range(40):
        start = time.perf_counter()
        granmix.hcs(**kw)
        total = time.perf_counter() - start
        totals.append(total)
        overheads.append(total - granmix._core._last_hcs_seconds())
    print(f'\ngranmix.hcs, binary: {1e3 * statistics.median(totals):.1f} ms per call (median of 40), of which the binding '
          f'(arguments, call, dict) {1e6 * statistics.median(overheads):.1f} µs')


# ------------------------------------------------------------------------------------------ scenes

def test_scene_reads_files_text_and_dicts_alike():
    path = SCENES / 'bo1-fig02.toml'
    s = granmix.Scene(path)
    assert (s.name, s.species, s.has_dsmc) == ('bo1-fig02', 2, True)
    assert s.file == str(path) and s.level and s.quantities
    assert s.times.dtype == np.float64 and s.times.ndim == 1
    t = granmix.Scene.from_toml(path.read_text(), str(path))
    assert t.to_toml() == s.to_toml()
    with open(path, 'rb') as f:
        d = granmix.Scene.from_dict(tomllib.load(f))
    assert (d.name, d.level, d.quantities, list(d.times)) == (s.name, s.level, s.quantities, list(s.times))
    assert 'bo1-fig02' in repr(s)


def test_a_scene_without_a_level_has_its_level_chosen_and_said_as_the_command_line_does(tmp_path):
    path = ROOT / 'examples' / 'ternary.toml'
    s = granmix.Scene(path)
    assert s.level != 'auto' and s.level_choice.startswith('auto chose ' + s.level)
    run_cli('theory', path, '--out', tmp_path)
    provenance = (tmp_path / 'example-ternary' / 'theory.tsv').read_text()
    assert '# level: ' + s.level_choice in provenance
    assert granmix.Scene(SCENES / 'mg-fig01.toml').level_choice == ''


def test_scene_errors_name_file_line_and_key_as_the_command_line_does(tmp_path):
    missing = tmp_path / 'missing.toml'
    with pytest.raises(granmix.SceneError) as e:
        granmix.Scene(missing)
    assert str(e.value) == cli_message(run_cli('theory', missing, '--out', tmp_path / 'out', check=False))
    bad = tmp_path / 'bad.toml'
    text = granmix.Scene.from_dict(TINY).to_toml().replace('restitution = 0.8', 'restitution = 1.8')
    bad.write_text(text)
    with pytest.raises(granmix.SceneError) as e:
        granmix.Scene.from_toml(text, str(bad))
    r = run_cli('theory', bad, '--out', tmp_path / 'out', check=False)
    assert r.returncode == 2 and str(e.value) == cli_message(r)
    assert str(e.value).startswith(f'{bad}:') and 'restitution' in str(e.value)
    unknown = dict(TINY, observables={'temperatures': True, 'colour': True})
    with pytest.raises(granmix.SceneError, match=r'^<dict>:\d+: .*colour'):
        granmix.Scene.from_dict(unknown)
    with pytest.raises(TypeError):
        granmix.Scene.from_dict(dict(TINY, collisions={'restitution': None}))
    with pytest.raises(TypeError):
        granmix.theory(42)


# ------------------------------------------------------------------------------------------ theory

# Small scenes, each in well under a second: temperatures, γ and c in time with the paper level's columns beside, a
# sweep of settled γ, and an MSD.
THEORY_SCENES = ['mg-fig01.toml', 'mg-fig04-mu2.toml', 'bo2-fig02-longtime.toml']


@pytest.mark.parametrize('name', THEORY_SCENES)
def test_theory_equals_the_command_line_tsv(name, tmp_path):
    result = granmix.theory(SCENES / name)
    run_cli('theory', SCENES / name, '--out', tmp_path)
    scene = granmix.Scene(SCENES / name)
    assert_same_table(result, tmp_path / scene.name / 'theory.tsv')
    assert result.level == scene.level and result.kind == 'theory'


def test_theory_of_one_level_equals_the_command_lines_level_option(tmp_path):
    name = 'mg-fig01.toml'
    result = granmix.theory(SCENES / name, level='kinetic')
    run_cli('theory', SCENES / name, '--out', tmp_path, '--level', 'kinetic')
    assert_same_table(result, tmp_path / 'mg-fig01' / 'theory_kinetic.tsv')
    assert result.level == 'kinetic'
    with pytest.raises(granmix.SceneError, match='^level: .*kinetic'):
        granmix.theory(SCENES / name, level='nonsense')


def test_a_solver_failure_is_a_solver_error_with_the_command_lines_message(tmp_path):
    # The sweep point where the converged HCS's operator turns singular (tests/compare/test_bad_input.cpp).
    text = ('[scene]\nname = "s"\n[mixture]\nspecies = [{ mass = 1, diameter = 1, density = 0.1 }, '
            '{ mass = 10000, diameter = 1, density = 0.001 }]\n[collisions]\nrestitution = 0.5\n'
            '[observables]\nd_ratio = true\n[theory]\nlevel = "kinetic-converged-hcs"\n'
            'sweep = { parameter = "eps", from = 0.3, to = 0.7, points = 2 }\n')
    path = tmp_path / 's.toml'
    path.write_text(text)
    with pytest.raises(granmix.SolverError) as e:
        granmix.theory(granmix.Scene.from_toml(text, str(path)))
    assert isinstance(e.value, RuntimeError)
    r = run_cli('theory', path, '--out', tmp_path / 'out', check=False)
    assert r.returncode == 3 and str(e.value) == cli_message(r)
    assert 'converged HCS' in str(e.value)


def test_results_are_float64_columns_of_one_length():
    r = granmix.theory(SCENES / 'mg-fig01.toml')
    assert r.columns[:2] == ['t', 'species'] and len(r) > 0
    for c in r.columns:
        assert r[c].dtype == np.float64 and r[c].shape == (len(r),)
    assert set(r) == set(r.columns) and 'T' in r and 'nonsense' not in r
    with pytest.raises(KeyError, match='nonsense'):
        r['nonsense']
    two = r.where(species=2)
    assert len(two) > 0 and np.all(two['species'] == 2)


def test_to_pandas_or_a_clear_import_error(monkeypatch):
    r = granmix.theory(SCENES / 'mg-fig01.toml')
    if importlib.util.find_spec('pandas') is not None:
        frame = r.to_pandas()
        assert list(frame.columns) == r.columns and len(frame) == len(r)
        assert np.array_equal(frame['t'].to_numpy(), r['t'])
    monkeypatch.setitem(sys.modules, 'pandas', None)  # as if pandas were not installed
    with pytest.raises(ImportError, match='pandas'):
        r.to_pandas()


# -------------------------------------------------------------------------------------------- dsmc

def test_dsmc_equals_the_command_line_tsv_and_any_thread_count(tiny_file, tmp_path):
    one = granmix.dsmc(tiny_file, threads=1)
    two = granmix.dsmc(granmix.Scene(tiny_file), fidelity='quick', seed=1, threads=2)
    assert one.columns == two.columns
    for c in one.columns:
        assert np.array_equal(one[c].view(np.uint64), two[c].view(np.uint64)), c
    run_cli('dsmc', tiny_file, '--out', tmp_path, '--threads', 2)
    assert_same_table(one, tmp_path / 'py-tiny' / 'dsmc.tsv')
    assert 'T_err' in one.columns and 'msd_err' in one.columns
    for c in one.columns:
        assert one[c].dtype == np.float64 and one[c].shape == (len(one),)
    assert one.info['particles'] == 2000 and one.info['replicas'] == 4 and one.info['collisions'] > 0
    other = granmix.dsmc(tiny_file, seed=2, threads=2)
    assert not np.array_equal(other['T'], one['T'])


def test_dsmc_refuses_bad_options():
    s = granmix.Scene.from_dict(TINY)
    with pytest.raises(granmix.SceneError, match='fidelity'):
        granmix.dsmc(s, fidelity='slow')
    with pytest.raises(granmix.SceneError, match='threads'):
        granmix.dsmc(s, threads=-1)
    with pytest.raises(TypeError):
        granmix.dsmc(s, particles=10)
    theory_only = {k: v for k, v in TINY.items() if k not in ('dsmc', 'compare')}
    with pytest.raises(granmix.SceneError, match=r'no \[dsmc\]'):
        granmix.dsmc(theory_only)


def test_sigint_during_dsmc_raises_keyboard_interrupt_and_the_module_lives_on():
    long_run = ROOT / 'tests' / 'scenes' / 'interrupt-long-dsmc.toml'  # minutes at quick fidelity
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)  # as in an interactive session
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            granmix.dsmc(long_run, threads=2)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    seconds = time.monotonic() - start
    assert 1.0 <= seconds < 30.0
    print(f'\nKeyboardInterrupt {seconds - 1.0:.2f} s after SIGINT')
    assert len(granmix.dsmc(TINY, threads=2)) > 0  # the module goes on working


# ----------------------------------------------------------------------------------------- compare

def test_compare_reports_as_report_json(tiny_file, tmp_path):
    report = granmix.compare(tiny_file, threads=2)
    run_cli('compare', tiny_file, '--out', tmp_path, '--threads', 2)
    cli = json.loads((tmp_path / 'py-tiny' / 'report.json').read_text())
    mine = report.to_dict()
    timing = {'theory_seconds', 'dsmc_seconds', 'collisions_per_second', 'figure'}
    same_json({k: v for k, v in mine.items() if k not in timing}, {k: v for k, v in cli.items() if k not in timing}, 'report')
    assert [q.name for q in report.quantities] == list(cli['quantities']) == ['T', 'msd[1,2]']
    for q in report.quantities:
        c = cli['quantities'][q.name]
        assert (q.max_rel, q.max_z, q.tolerance) == (c['max_rel'], c['max_z'], c['tolerance'])
        assert q.passed == (c['failed'] == 0 and c['judged'] > 0)
    assert report.passed == cli['pass'] and report['T'].tolerance['relative'] == 0.05
    assert_same_table(report.theory, tmp_path / 'py-tiny' / 'theory.tsv')
    assert_same_table(report.dsmc, tmp_path / 'py-tiny' / 'dsmc.tsv')
    columns, dev = read_tsv_deviations(tmp_path / 'py-tiny' / 'deviations.tsv')
    assert report.deviations.columns == columns
    for c in ('t', 'species', 'theory', 'dsmc', 'dsmc_err', 'rel', 'z'):
        assert np.array_equal(report.deviations[c], dev[c], equal_nan=True), c
    assert 'py-tiny' in repr(report)


def read_tsv_deviations(path):
    lines = [l for l in pathlib.Path(path).read_text().splitlines() if l and not l.startswith('#')]
    columns = lines[0].split('\t')
    rows = [l.split('\t') for l in lines[1:]]
    data = {c: [r[i] for r in rows] for i, c in enumerate(columns)}
    return columns, {c: np.array([float(x) for x in v]) for c, v in data.items() if c not in ('quantity', 'judged', 'pass', 'resolved')}


def test_levels_are_the_catalogues():
    levels = granmix.levels()
    names = [l['name'] for l in levels]
    listing = run_cli('levels', '--all').stdout
    assert all(n in listing for n in names)
    chosen = run_cli('levels').stdout
    for l in levels:
        assert set(l) >= {'name', 'family', 'summary', 'applies', 'cost', 'scene_may_choose'}
        if l['scene_may_choose']:
            assert l['name'] in chosen
    assert 'paper' in names and any(not l['scene_may_choose'] for l in levels)


# ---------------------------------------------------------------------------------------- examples

def module_env():
    """The environment with this granmix's folder on PYTHONPATH, as an absolute path (examples run in other folders)."""
    folder = str(pathlib.Path(granmix.__file__).resolve().parents[1])
    return dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [folder, os.environ.get('PYTHONPATH')])))


def run_example(*args, cwd):
    r = subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=600, env=module_env())
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def test_example_hcs_scan(tmp_path):
    out = run_example(EXAMPLES / 'hcs_scan.py', '--masses', 3, '--eps', 4, cwd=tmp_path)
    assert '12 points in' in out and 'T2/T1' in out and 'D2/D1' in out


def test_example_ternary(tmp_path):
    pytest.importorskip('matplotlib')
    png = tmp_path / 'ternary.png'
    out = run_example(EXAMPLES / 'ternary.py', png, '--particles', 1500, '--replicas', 2, '--end', 10, '--level', 'kinetic',
                      cwd=tmp_path)
    assert png.stat().st_size > 10000 and png.read_bytes()[:8] == b'\x89PNG\r\n\x1a\n'
    assert 'bo1-fig06' in out


def test_example_notebook_runs_headless(tmp_path):
    pytest.importorskip('nbconvert', reason='jupyter nbconvert is not installed')
    pytest.importorskip('matplotlib')
    from jupyter_client.kernelspec import find_kernel_specs
    if 'python3' not in find_kernel_specs():
        pytest.skip('no python3 Jupyter kernel (ipykernel)')
    r = subprocess.run([sys.executable, '-m', 'nbconvert', '--to', 'notebook', '--execute', '--output-dir', str(tmp_path),
                        str(EXAMPLES / 'scan.ipynb')], capture_output=True, text=True, timeout=600, env=module_env())
    assert r.returncode == 0, r.stderr
    executed = json.loads((tmp_path / 'scan.ipynb').read_text())
    outputs = [o for c in executed['cells'] if c['cell_type'] == 'code' for o in c['outputs']]
    assert any('points in' in ''.join(o.get('text', '')) for o in outputs)


def test_the_committed_notebook_has_no_outputs():
    nb = json.loads((EXAMPLES / 'scan.ipynb').read_text())
    for c in nb['cells']:
        if c['cell_type'] == 'code':
            assert c['outputs'] == [] and c['execution_count'] is None
