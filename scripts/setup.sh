#!/usr/bin/env bash
# Installs the Debian 12 packages collide needs, only those that are missing (silent and fast
# when everything is there). Usage: scripts/setup.sh [--test]   (--test adds ffmpeg, xvfb, chromium
# and file: CPack's DEB generator needs `file` to find the binaries whose libraries
# dpkg-shlibdeps reads, and a minimal Debian 12 image has none; lintian checks the .deb and
# groff-base the generated man page; poppler-utils reads the handout PDF back: pdfinfo, pdftoppm)
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config python3-glad
    libosmesa6-dev libegl-dev libglfw3-dev libstb-dev fonts-dejavu-core fonts-droid-fallback
    libfreetype-dev libharfbuzz-dev libfribidi-dev libcairo2-dev
    libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libavfilter-dev
    libcli11-dev libtomlplusplus-dev libfmt-dev nlohmann-json3-dev doctest-dev libbenchmark-dev
)
if [[ "${1:-}" == "--test" ]]; then
    packages+=(ffmpeg xvfb xauth clang-format chromium file lintian groff-base poppler-utils)
fi

missing=()
for p in "${packages[@]}"; do
    if [[ "$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null)" != "installed" ]]; then
        missing+=("$p")
    fi
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

sudo=()
if [[ "$(id -u)" -ne 0 ]]; then
    if ! command -v sudo >/dev/null; then
        echo "setup: need root or sudo to install: ${missing[*]}" >&2
        exit 1
    fi
    sudo=(sudo)
fi
echo "==> installing missing Debian packages: ${missing[*]}"
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
