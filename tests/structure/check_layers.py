#!/usr/bin/env python3
"""Fails on an include that points up the layers (docs/architecture.md §2).

Folders: model < theory, dsmc < bench < compare < python (the module's bindings); tests, scripts and tools may include
anything.
Inside theory/, the wings: numerics < rates < histories < sonine < grid < levels < the door (theory/*.hpp).
A file may include its own layer or wing and those below it, never one above."""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
LAYERS = {'model': 0, 'theory': 1, 'dsmc': 1, 'bench': 2, 'compare': 3, 'python': 4}
# dsmc may ask theory for an initial state (the HCS ratios), never the other way round.
ALLOWED_SIDEWAYS = {('dsmc', 'theory')}
WINGS = ['numerics', 'rates', 'histories', 'sonine', 'grid', 'levels']
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def wing_rank(rel: pathlib.PurePosixPath) -> int:
    """The wing of a path under theory/: its index in WINGS; the door (theory/x.hpp) ranks above every wing."""
    parts = rel.parts
    if len(parts) == 2:
        return len(WINGS)
    if parts[1] not in WINGS:
        raise SystemExit(f'{rel}: theory/{parts[1]}/ is not a declared wing ({", ".join(WINGS)}): add it to {__file__}')
    return WINGS.index(parts[1])


def resolve(src: pathlib.Path, target: str) -> pathlib.PurePosixPath | None:
    for base in (ROOT, src.parent):
        p = base / target
        if p.exists():
            return pathlib.PurePosixPath(p.resolve().relative_to(ROOT))
    return None


problems = []
checked = 0
for layer in LAYERS:
    for src in sorted((ROOT / layer).rglob('*')):
        if src.suffix not in ('.hpp', '.cpp', '.h'):
            continue
        rel = pathlib.PurePosixPath(src.relative_to(ROOT))
        for target in INCLUDE.findall(src.read_text(encoding='utf-8')):
            dst = resolve(src, target)
            if dst is None or dst.parts[0] not in LAYERS:
                continue  # generated headers (granmix_version.hpp) and libraries
            checked += 1
            a, b = rel.parts[0], dst.parts[0]
            if a != b and LAYERS[b] >= LAYERS[a] and (a, b) not in ALLOWED_SIDEWAYS:
                problems.append(f'{rel}: includes {dst}, a layer not below {a}/')
            if a == b == 'theory' and wing_rank(dst) > wing_rank(rel):
                problems.append(f'{rel}: includes {dst}, a wing above its own (order: {" < ".join(WINGS)} < door)')

for p in problems:
    print(p)
print(f'{checked} includes between granmix headers checked, {len(problems)} pointing upward')
sys.exit(1 if problems or checked == 0 else 0)
