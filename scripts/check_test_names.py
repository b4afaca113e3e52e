#!/usr/bin/env python3
"""Every doctest TEST_CASE name under tests/ can be one ctest test.

doctest_discover_tests hands the names to CMake as a list, whose separator is ';': a name with a
';' is split into two tests that each match no case, and both fail with a message that names
neither. This check names the file and line instead. Exit 1 when a name has one.
"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent / "tests"
case = re.compile(r'TEST_CASE\(((?:\s*"(?:[^"\\]|\\.)*")+)')
bad = 0
for path in sorted(root.rglob("*.cpp")):
    text = path.read_text(encoding="utf-8")
    for match in case.finditer(text):
        name = "".join(re.findall(r'"((?:[^"\\]|\\.)*)"', match.group(1)))
        if ";" in name:
            line = text.count("\n", 0, match.start()) + 1
            print(f"{path.relative_to(root.parent)}:{line}: a ';' in the test name '{name}' "
                  "(CMake's list separator: ctest would split it in two)")
            bad += 1
sys.exit(1 if bad else 0)
