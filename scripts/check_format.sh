#!/usr/bin/env bash
# Checks that every tracked C and C++ file is formatted as .clang-format says (clang-format 14,
# Debian 12's). Usage: scripts/check_format.sh [--fix]. Exit 0 when all are, 1 (listing the files)
# when not; 77 (skipped) without clang-format or outside a git checkout.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "SKIP: clang-format not installed"; exit 77; }
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || { echo "SKIP: not a git checkout"; exit 77; }
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.c')
if [[ "${1:-}" == "--fix" ]]; then
    clang-format -i "${files[@]}"
    exit 0
fi
# One clang-format for all files; its warnings start with the file's name.
mapfile -t bad < <(clang-format --dry-run -Werror "${files[@]}" 2>&1 |
                   grep -oE '^[^: ]+\.(cpp|hpp|h|c):[0-9]+:[0-9]+: (warning|error)' |
                   cut -d: -f1 | sort -u || true)
if [[ ${#bad[@]} -gt 0 ]]; then
    echo "not formatted (run scripts/check_format.sh --fix, or clang-format -i FILE):"
    printf '  %s\n' "${bad[@]}"
    exit 1
fi
echo "format: ${#files[@]} files as .clang-format says"
