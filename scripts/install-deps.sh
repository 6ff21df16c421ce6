#!/usr/bin/env bash
# Installs every build/test dependency of cloudsvc from Debian 12 packages.
# Idempotent: does nothing (no apt-get update) when all packages are already present.
set -euo pipefail

PACKAGES=(
  g++ cmake make pkgconf
  clang libclang-rt-14-dev
  libglfw3-dev libglm-dev libgeographiclib-dev
  libepoxy-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libopenimageio-dev openimageio-tools libimath-dev fonts-dejavu-core
  libgtest-dev libgmock-dev
  libcli11-dev nlohmann-json3-dev libspdlog-dev libfmt-dev
  libflatbuffers-dev flatbuffers-compiler libasio-dev
  libeccodes-dev libeccodes-tools  # the tools: eccodes-targets.cmake checks /usr/bin/codes_info exists
  xvfb xauth
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
