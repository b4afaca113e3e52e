#!/usr/bin/env bash
# The installed program stands alone (issue #31): install to a temporary prefix, move the prefix,
# make the source tree unreachable, and run every kind of command from another directory.
# Usage: install_test.sh CMAKE BUILD_DIR SOURCE_DIR
# How it proves that the program reads the moved prefix and never the source tree:
#  - the moved prefix gets a scene the source tree lacks (installed-only) and loses one it has
#    (tunnelling): `scenes` must list the first and not the second, `check tunnelling` must fail;
#  - where user namespaces are allowed (unshare -rm), the commands run with an empty tmpfs
#    mounted over the source tree (and with it the build tree inside it), so no file of it can be
#    opened; elsewhere that part is reported as not run.
set -euo pipefail
cmake_bin=$1 build=$2 source=$3

tmp=$(mktemp -d "${TMPDIR:-/tmp}/collide-install-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
"$cmake_bin" --install "$build" --prefix "$tmp/first" >/dev/null
mv "$tmp/first" "$tmp/moved"
prefix=$tmp/moved
test -x "$prefix/bin/collide"
test -x "$prefix/libexec/collide/collide-draw"
test -f "$prefix/share/man/man1/collide.1.gz"
test -f "$prefix/share/bash-completion/completions/collide"
test -f "$prefix/share/zsh/vendor-completions/_collide"
test -f "$prefix/share/fish/vendor_completions.d/collide.fish"
test -f "$prefix/share/collide/scenes/gas.toml"
cp "$prefix/share/collide/scenes/gas.toml" "$prefix/share/collide/scenes/installed-only.toml"
rm "$prefix/share/collide/scenes/tunnelling.toml"
mkdir "$tmp/work"

# The commands, run from $tmp/work with no data variable set: written to a file so that it can
# run inside the namespace where the source tree (holding this script) is hidden.
cat >"$tmp/commands.sh" <<'COMMANDS'
set -euo pipefail
prefix=$1 source=$2
unset COLLIDE_DATA_DIR COLLIDE_ASSETS_DIR COLLIDE_FONT
cd "$(dirname "$prefix")/work"
collide=$prefix/bin/collide
fail() { echo "FAIL: $*" >&2; exit 1; }
if [[ -n "${HIDDEN:-}" ]]; then
    [[ -z "$(ls -A "$source")" ]] || fail "the source tree is still visible"
fi
"$collide" --version | tee version.txt
grep -q "^data: $prefix/share/collide (next to the program)" version.txt || fail "--version data"
"$collide" scenes > scenes.txt
grep -q '^installed-only ' scenes.txt || fail "scenes does not list the installed-only scene"
! grep -q '^tunnelling ' scenes.txt || fail "scenes lists a scene that only the source tree has"
"$collide" check installed-only
status=0; "$collide" check tunnelling 2> check.err || status=$?
[[ $status -eq 2 ]] || fail "check tunnelling exited $status, expected 2 (not installed)"
"$collide" check gas --json > check.json
grep -q '"discs": 20' check.json || fail "check --json"
"$collide" render gas -q l --size 160x90 --duration 0.5 -o r.mp4 --progress none
[[ -s r.mp4 ]] || fail "render wrote nothing"
"$collide" thumbnail gas --at 1 --size 160x90 -o t.png
[[ -s t.png ]] || fail "thumbnail wrote nothing"
"$collide" heap --ops "P Q *" --size 320x180 --at 1 -o h.png
[[ -s h.png ]] || fail "heap wrote nothing"
"$collide" puzzle "1 2 3 4 5 6 7 0 8" -q l --at 1 -o p.png
[[ -s p.png ]] || fail "puzzle wrote nothing"
"$collide" puzzle "1 2 3 4 5 6 7 0 8" --solve
# The data directory can also be named.
mkdir -p alt/scenes && cp "$prefix/share/collide/scenes/gas.toml" alt/scenes/only-here.toml
[[ "$(COLLIDE_DATA_DIR=$PWD/alt "$collide" scenes | awk '{print $1}')" == only-here ]] ||
    fail "COLLIDE_DATA_DIR is not used"
echo "install test: all commands passed${HIDDEN:+ with the source tree hidden}"
COMMANDS

# Not in the source tree: the commands run while it is hidden.
cp "$tmp/commands.sh" "$tmp/run.sh"
if unshare -rm true 2>/dev/null; then
    HIDDEN=1 unshare -rm bash -c 'mount -t tmpfs none "$2" && exec bash "$3" "$1" "$2"' \
        _ "$prefix" "$source" "$tmp/run.sh"
else
    echo "note: unshare -rm is not allowed here: the source tree stays visible (the scene" \
         "checks above still tell the prefix's data from the source tree's)"
    bash "$tmp/run.sh" "$prefix" "$source"
fi
