#!/usr/bin/env bash
# The .deb (issues #31, #46): CPack builds it from this build tree, its dependencies come from
# the libraries the program links (dpkg-shlibdeps), its files work where dpkg puts them, and
# lintian (default profile) has nothing to say about it: no error, no warning.
# Usage: deb_test.sh CPACK BUILD_DIR. Exits 77 (skipped) without dpkg-deb and dpkg-shlibdeps;
# without lintian the lintian check alone is skipped, and says so.
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
[[ $(dpkg-deb -f "$deb" Recommends) == *fonts-droid-fallback* ]] ||
    fail "Recommends lacks fonts-droid-fallback (the CJK fallback font)"
contents=$(dpkg-deb -c "$deb")
grep -q './usr/bin/collide$' <<<"$contents" || fail "no /usr/bin/collide"
grep -q './usr/libexec/collide/collide-draw$' <<<"$contents" || fail "no collide-draw"
grep -q './usr/share/collide/scenes/gas.toml$' <<<"$contents" || fail "no scenes"
grep -q './usr/share/man/man1/collide.1.gz$' <<<"$contents" || fail "no compressed man page"
grep -q './usr/share/bash-completion/completions/collide$' <<<"$contents" || fail "no bash completion"
grep -q './usr/share/zsh/vendor-completions/_collide$' <<<"$contents" || fail "no zsh completion"
grep -q './usr/share/fish/vendor_completions.d/collide.fish$' <<<"$contents" || fail "no fish completion"
grep -q './usr/share/doc/collide/copyright$' <<<"$contents" || fail "no copyright file"
grep -q './usr/share/doc/collide/changelog.Debian.gz$' <<<"$contents" || fail "no changelog"
[[ $(dpkg-deb -f "$deb" Version) =~ ^[0-9.]+-[0-9]+$ ]] || fail "Version has no Debian revision"
[[ $(dpkg-deb -f "$deb" Maintainer) != *localhost* ]] || fail "Maintainer at localhost"
# Stripped: no .debug_info section left in either program.
dpkg-deb -x "$deb" "$tmp/stripped"
for program in usr/bin/collide usr/libexec/collide/collide-draw; do
    ! readelf -S "$tmp/stripped/$program" | grep -q '\.debug_info' || fail "$program is not stripped"
done
if command -v lintian >/dev/null; then
    # --no-cfg: the machine's lintianrc must not change the profile; errors and warnings only
    # (lintian's default display level).
    # As root it also says that root is not recommended: that line is about the caller.
    findings=$(lintian --no-cfg "$deb" 2>&1 | grep -v 'running with root privileges') || true
    [[ -z "$findings" ]] || fail "lintian: $findings"
    echo "lintian: nothing to report"
else
    echo "SKIP (lintian check only): lintian is not installed (scripts/setup.sh --test)"
fi
# Unpacked anywhere, the program finds the package's scenes (../share/collide) and renders.
dpkg-deb -x "$deb" "$tmp/root"
cd "$tmp"
env -u COLLIDE_DATA_DIR -u COLLIDE_ASSETS_DIR "$tmp/root/usr/bin/collide" check gas
env -u COLLIDE_DATA_DIR -u COLLIDE_ASSETS_DIR "$tmp/root/usr/bin/collide" \
    thumbnail gas --size 160x90 --at 1 -o "$tmp/gas.png"
[[ -s "$tmp/gas.png" ]] || fail "no thumbnail"
echo "deb test: $(basename "$deb") passed"
