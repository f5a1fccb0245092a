"""granmix: the kinetic theory of freely cooling granular gas mixtures beside DSMC, from Python (docs/python.md).

The functions call the same code as the command line; a table comes back as a Result with one float64 array per
column of theory.tsv or dsmc.tsv.

    import granmix
    scene = granmix.Scene("compare/scenes/bo1-fig02.toml")
    theory = granmix.theory(scene)              # theory.tsv's columns: theory["t"], theory["msd"], ...
    dsmc = granmix.dsmc(scene, fidelity="quick") # dsmc.tsv's: means and their standard errors (X_err)
    report = granmix.compare(scene)              # per compared quantity: max deviation, max z, tolerance, pass
    granmix.hcs(mass=[1, 2], diameter=[1, 1], density=[0.1, 0.1], eps=0.8)["species"][1]["T_ratio_sonine"]
"""
import dataclasses
import os

import numpy as np

from . import _toml
from ._core import Scene, SceneError, SolverError, __version__, git_sha, hcs, levels
from ._core import _compare, _dsmc, _theory

__all__ = ['Scene', 'SceneError', 'SolverError', 'Result', 'Report', 'Quantity', 'hcs', 'levels', 'theory', 'dsmc',
           'compare', '__version__']


def _from_dict(scene, path='<dict>'):
    """A scene from a dict of tables ({"scene": {...}, "mixture": {...}, ...}), written as TOML and then read and
    checked as a scene file is; `path` names it in messages (file:line points into to_toml()'s text)."""
    return Scene.from_toml(_toml.dumps(scene), path)


Scene.from_dict = staticmethod(_from_dict)


def _scene(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, os.PathLike)):
        return Scene(scene)
    if isinstance(scene, dict):
        return Scene.from_dict(scene)
    raise TypeError(f'scene: a granmix.Scene, a path or a dict, not {type(scene).__name__}')


class Result:
    """A table as granmix writes it (theory.tsv, dsmc.tsv; docs/architecture.md §4): long form, one row per
    (location, species), one numpy array per column. result["T"], result.columns, len(result) (rows), result.level
    (theory), result.info (timings, solver or DSMC counts). NaN where a column does not apply to a row."""

    def __init__(self, kind, columns, data, level=None, info=None, distribution=None):
        self.kind = kind
        self.columns = list(columns)
        self._data = data
        self.level = level
        self.info = dict(info or {})
        self.distribution = distribution  # dsmc: distribution.tsv's table when the scene asks for one

    @classmethod
    def _from_core(cls, kind, d, level=None):
        distribution = d.get('distribution')
        if distribution is not None:
            distribution = cls(kind, distribution['columns'], distribution['data'])
        return cls(kind, d['columns'], d['data'], level=d.get('level', level), info=d.get('info'),
                   distribution=distribution)

    def __getitem__(self, column):
        try:
            return self._data[column]
        except KeyError:
            raise KeyError(f'{column!r}: not a column of this {self.kind} table (columns: {", ".join(self.columns)})') from None

    def __contains__(self, column):
        return column in self._data

    def __iter__(self):
        return iter(self.columns)

    def keys(self):
        return list(self.columns)

    def __len__(self):
        return len(self._data[self.columns[0]]) if self.columns else 0

    def where(self, **equal):
        """The rows where each named column equals its value, e.g. result.where(species=2)."""
        keep = np.ones(len(self), dtype=bool)
        for column, value in equal.items():
            keep &= self[column] == value
        return Result(self.kind, self.columns, {c: self._data[c][keep] for c in self.columns}, self.level, self.info)

    def to_pandas(self):
        """A pandas DataFrame of the columns (pandas is optional: ImportError without it)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError('Result.to_pandas needs pandas (Debian: python3-pandas); without it, '
                              'result[column] gives each column as a numpy array') from e
        return pandas.DataFrame({c: self._data[c] for c in self.columns})

    def __repr__(self):
        level = f', level {self.level}' if self.level else ''
        return f'<granmix.Result {self.kind}{level}: {len(self)} rows; columns {", ".join(self.columns)}>'


@dataclasses.dataclass(frozen=True)
class Quantity:
    """One compared quantity of a Report (report.json's entry): name is its label ("msd", "msd[2,3]"); max_rel the
    largest |dsmc − theory|/|theory| and max_z the largest |z| over the judged points; tolerance its parts (relative,
    z and, when set, correction_from, error_column, model_error_max, absolute); passed whether every judged point
    passed (and at least one was judged)."""
    name: str
    max_rel: float
    max_z: float
    tolerance: dict
    passed: bool
    points: int
    judged: int
    failed: int
    unresolved: int
    max_model_error: float
    paper_max_rel: float | None
    why: str = dataclasses.field(repr=False)


class Report:
    """A scene compared: theory against DSMC, point by point, judged by the scene's tolerances (docs/judging.md).
    report.passed, report.quantities (Quantity each), report["msd"], report.theory and report.dsmc (Result),
    report.deviations (deviations.tsv's columns), report.to_dict() (report.json's object)."""

    def __init__(self, d):
        self._report = d['report']
        self.scene = self._report['scene']
        self.passed = bool(self._report['pass'])
        self.compared = bool(d['compared'])
        self.quantities = [
            Quantity(name=name, max_rel=q['max_rel'], max_z=q['max_z'], tolerance=dict(q['tolerance']), passed=bool(d['passes'][name]),
                     points=q['points'], judged=q['judged'], failed=q['failed'], unresolved=q['unresolved'],
                     max_model_error=q['max_model_error'], paper_max_rel=q.get('paper_max_rel'), why=q['why'])
            for name, q in self._report['quantities'].items()]
        self.theory = Result._from_core('theory', d['theory'])
        self.dsmc = Result._from_core('dsmc', d['dsmc']) if d['dsmc'] is not None else None
        dev = d['deviations']
        columns = [d['x']] + [c for c in dev if c != 'x']
        self.deviations = Result('deviations', columns, {(d['x'] if c == 'x' else c): np.asarray(v) for c, v in dev.items()})

    def __getitem__(self, name):
        for q in self.quantities:
            if q.name == name:
                return q
        raise KeyError(f'{name!r}: not a compared quantity of {self.scene} ({", ".join(q.name for q in self.quantities)})')

    def to_dict(self):
        """report.json's object (docs/architecture.md §4), without a figure."""
        return self._report

    def __repr__(self):
        lines = [f'<granmix.Report {self.scene}: {"pass" if self.passed else "FAIL"}']
        for q in self.quantities:
            lines.append(f'  {q.name}: max rel {q.max_rel:.3g}, max |z| {q.max_z:.3g}, '
                         f'{q.judged}/{q.points} judged, {"pass" if q.passed else "FAIL"}')
        return '\n'.join(lines) + '>'


def theory(scene, level=None):
    """The theory curves of a scene (granmix theory): its judged level with the paper level's and the companions'
    columns (theory.tsv); level="NAME": that level's curves alone (granmix theory --level, any level of levels())."""
    return Result._from_core('theory', _theory(_scene(scene), level))


def dsmc(scene, fidelity='quick', seed=1, threads=0):
    """The scene's DSMC (granmix dsmc): dsmc.tsv's columns, each mean X beside its standard error X_err over the
    replicas. Bit-identical for any thread count (threads=0: all cores). Ctrl-C raises KeyboardInterrupt within a
    refresh interval of the replicas."""
    return Result._from_core('dsmc', _dsmc(_scene(scene), fidelity, seed, threads))


def compare(scene, fidelity='quick', seed=1, threads=0):
    """The scene compared (granmix compare, without its files): theory, DSMC and the judgement per quantity."""
    return Report(_compare(_scene(scene), fidelity, seed, threads))
