#!/usr/bin/env bash
# The .deb (issue #31): CPack builds it from this build tree, its dependencies come from the
# libraries the program links (dpkg-shlibdeps), and its files work where dpkg puts them.
# Usage: deb_test.sh CPACK BUILD_DIR. Exits 77 (skipped) without dpkg-deb and dpkg-shlibdeps.
set -euo pipefail
cpack_bin=$1 build=$2
for tool in dpkg-deb dpkg-shlibdeps; do
    command -v "$tool" >/dev/null || { echo "SKIP: no $tool (dpkg-dev)"; exit 77; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/collide-deb-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
"$cpack_bin" -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/out" >"$tmp/cpack.log" 2>&1 ||
    { cat "$tmp/cpack.log"; exit 1; }
deb=$(ls "$tmp"/out/collide_*.deb)
fail() { echo "FAIL: $*" >&2; exit 1; }
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for library in libavcodec libavformat libavutil libosmesa6 libglfw3 fonts-dejavu-core; do
    [[ $depends == *"$library"* ]] || fail "Depends lacks $library"
done
contents=$(dpkg-deb -c "$deb")
grep -q './usr/bin/collide$' <<<"$contents" || fail "no /usr/bin/collide"
grep -q './usr/libexec/collide/collide-draw$' <<<"$contents" || fail "no collide-draw"
grep -q './usr/share/collide/scenes/gas.toml$' <<<"$contents" || fail "no scenes"
grep -q './usr/share/man/man1/collide.1' <<<"$contents" || fail "no man page"
grep -q './usr/share/bash-completion/completions/collide$' <<<"$contents" || fail "no completion"
# Unpacked anywhere, the program finds the package's scenes (../share/collide) and renders.
dpkg-deb -x "$deb" "$tmp/root"
cd "$tmp"
env -u COLLIDE_DATA_DIR -u COLLIDE_ASSETS_DIR "$tmp/root/usr/bin/collide" check gas
env -u COLLIDE_DATA_DIR -u COLLIDE_ASSETS_DIR "$tmp/root/usr/bin/collide" \
    thumbnail gas --size 160x90 --at 1 -o "$tmp/gas.png"
[[ -s "$tmp/gas.png" ]] || fail "no thumbnail"
echo "deb test: $(basename "$deb") passed"
