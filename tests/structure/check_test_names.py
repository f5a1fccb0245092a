#!/usr/bin/env python3
"""Every Catch2 test is one ctest test: its name has no ';' (ctest's list separator, which splits the name
into two tests that match nothing and fail). Usage: check_test_names.py SOURCE_DIR; exit 1 naming each one."""
import re
import sys
from pathlib import Path

root = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
# TEST_CASE( followed by one or more adjacent string literals (a long name is split over lines).
name = re.compile(r'TEST_CASE\s*\(\s*((?:"(?:[^"\\]|\\.)*"\s*)+)')
bad = []
for f in sorted((root / "tests").rglob("*.cpp")):
    text = f.read_text(errors="replace")
    for m in name.finditer(text):
        joined = "".join(re.findall(r'"((?:[^"\\]|\\.)*)"', m.group(1)))
        if ";" in joined:
            line = text.count("\n", 0, m.start()) + 1
            bad.append(f"{f.relative_to(root)}:{line}: test name has ';' (ctest splits it in two): {joined}")
print("\n".join(bad) if bad else f"test names: none has ';'")
sys.exit(1 if bad else 0)
