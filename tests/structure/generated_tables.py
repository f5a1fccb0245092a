#!/usr/bin/env python3
"""The tables the docs take from the code's catalogues, checked (or rewritten with --write).

docs/levels.md holds `granmix levels --all --markdown` and docs/scenes.md `granmix observables --markdown`, each between
its BEGIN and END marker lines. Usage: generated_tables.py GRANMIX [REPO] [--write]."""
import pathlib
import re
import subprocess
import sys

args = [a for a in sys.argv[1:] if a != '--write']
write = '--write' in sys.argv
granmix = args[0]
root = pathlib.Path(args[1] if len(args) > 1 else pathlib.Path(__file__).resolve().parents[2])
TABLES = [('docs/levels.md', 'levels table', ['levels', '--all', '--markdown']),
          ('docs/scenes.md', 'observables table', ['observables', '--markdown'])]
stale = 0
for page, name, command in TABLES:
    path = root / page
    text = path.read_text(encoding='utf-8')
    want = subprocess.run([granmix, *command], capture_output=True, text=True, check=True).stdout
    pattern = re.compile(rf'(<!-- BEGIN {name}[^\n]*-->\n)(.*?)(<!-- END {name} -->)', re.S)
    m = pattern.search(text)
    if not m:
        print(f'{page}: no "<!-- BEGIN {name} ... -->" ... "<!-- END {name} -->" markers')
        stale += 1
        continue
    if m.group(2) == want:
        continue
    if write:
        path.write_text(text[:m.start(2)] + want + text[m.end(2):], encoding='utf-8')
        print(f'{page}: {name} rewritten from granmix {" ".join(command)}')
    else:
        print(f'{page}: the {name} differs from `granmix {" ".join(command)}`: regenerate with {sys.argv[0]} {granmix} --write')
        stale += 1
sys.exit(1 if stale else 0)
