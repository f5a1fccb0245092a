#!/usr/bin/env python3
"""Every page the project cites is inside the repository, and the product carries no development diary.

1. Links of README.md and docs/*.md: a relative link names a file that exists; an anchor (#...) names a heading of it.
2. Citations of docs pages anywhere in the tracked files (code comments, scenes, scripts): `docs/<page>.md` exists,
   `docs/<page>.md §N` has a heading numbered N, `docs/<page>.md, "Title"` a heading that contains Title.
3. Nothing cites pages a clone does not have (the shared folder beside the repository, or the physics and design
   pages by their bare file names outside docs/) or README sections
   (the README is a front door: the docs pages carry the rest).
4. No development history: a numbered stop of the work, a rehearsal of CI (docs/architecture.md §7).
Run from anywhere: check_docs.py [REPO]."""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]).resolve()
listed = subprocess.run(['git', 'ls-files'], cwd=ROOT, capture_output=True, text=True)
if listed.returncode == 0:
    files = listed.stdout.split()
else:  # a copy without git (the mutation harness's scratch tree): the source folders as they are
    skip = ('build', 'out', '.git')
    files = [p.relative_to(ROOT).as_posix() for p in ROOT.rglob('*')
             if p.is_file() and not p.relative_to(ROOT).parts[0].startswith(skip)]
text_of = {}
for f in files:
    p = ROOT / f
    if p.suffix in ('.png', '.pdf', '.gz') or 'fuzz/corpus' in f or not p.is_file():
        continue
    try:
        text_of[f] = p.read_text(encoding='utf-8')
    except UnicodeDecodeError:
        continue

HEADING = re.compile(r'^#{1,6}\s+(.*?)\s*#*\s*$', re.M)


def headings(page: str) -> list[str]:
    body = re.sub(r'```.*?```', '', text_of.get(page, ''), flags=re.S)
    return [h.strip() for h in HEADING.findall(body)]


def slug(title: str) -> str:  # GitHub's anchors: lower case, punctuation dropped, spaces to hyphens
    s = re.sub(r'[`*_]', '', title.strip().lower())
    s = re.sub(r'[^\w\- ]', '', s)
    return s.replace(' ', '-')


problems = []
pages = [f for f in text_of if f.endswith('.md') and (f == 'README.md' or f.startswith('docs/'))]
LINK = re.compile(r'(?<!!)\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)|!\[[^\]]*\]\(([^)\s]+)\)')
for page in pages:
    body = re.sub(r'```.*?```', '', text_of[page], flags=re.S)
    for m in LINK.finditer(body):
        target = m.group(1) or m.group(2)
        if re.match(r'^[a-z]+:', target):
            continue
        path, _, anchor = target.partition('#')
        dest = (ROOT / page).parent / path if path else ROOT / page
        rel = dest.resolve().relative_to(ROOT).as_posix() if dest.resolve().is_relative_to(ROOT) else None
        if rel is None or not dest.exists():
            problems.append(f'{page}: link to {target}: no such file in the repository')
        elif anchor and rel.endswith('.md') and anchor not in {slug(h) for h in headings(rel)}:
            problems.append(f'{page}: link to {target}: {rel} has no heading with anchor #{anchor}')

CITE = re.compile(r'(?<![\w/.-])(docs/[\w./-]+?\.md)(?:(,? §)(\d+)|,? "([^"]+)")?')
for f, body in text_of.items():
    for m in CITE.finditer(body):
        page, number, title = m.group(1), m.group(3), m.group(4)
        line = body.count('\n', 0, m.start()) + 1
        if page not in text_of:
            problems.append(f'{f}:{line}: cites {page}, which is not in the repository')
            continue
        if number and not any(re.match(rf'{number}[.\s]', h) for h in headings(page)):
            problems.append(f'{f}:{line}: cites {page} §{number}, which has no heading numbered {number}')
        if title and not any(title.lower() in h.lower() for h in headings(page)):
            problems.append(f'{f}:{line}: cites {page}, "{title}", which has no such heading')

# Spelt in parts, so that this file neither matches itself nor is rewritten by a citation fix-up.
SHARED = '../' + 'shared/'
BARE = '|'.join(('physics', 'physics' + '-beyond', 'design'))
OUTSIDE = re.compile(re.escape(SHARED) + r'|(?<![\w/.-])(?:' + BARE + r')\.md|README,? "')
HISTORY = re.compile('[Ss]' + 'top [0-9]+|CI ' + 'rehearsal')  # split: this file must not match itself
for f, body in text_of.items():
    if f == 'tests/structure/check_docs.py':
        continue
    for i, line in enumerate(body.split('\n'), 1):
        if (SHARED in line or not f.startswith('docs/')) and OUTSIDE.search(line):  # docs/ link their pages by name
            problems.append(f'{f}:{i}: cites a page outside the repository or a README section: {line.strip()[:120]}')
        if HISTORY.search(line):
            problems.append(f'{f}:{i}: development history: {line.strip()[:120]}')

for p in problems:
    print(p)
print(f'{len(pages)} pages, {len(text_of)} files checked: {len(problems)} problems')
sys.exit(1 if problems else 0)
