#!/usr/bin/env bash
# Shared by scripts/run and scripts/test: installs the Debian packages Impetus needs when they are
# missing (with sudo when not root), then configures and builds the `release` preset.
# Source it; it defines impetus_setup.
set -euo pipefail

IMPETUS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Build tools, the engine's libraries, Qt for the app, Qt Linguist's tools for the translations
# (lrelease at build time, the CMake package), fonts so that text renders offscreen, Doxygen, so
# that the test suite checks that the engine's API reference builds without a warning, and Xvfb,
# the X server the autosave test runs the real app on before it kills it (with xauth, which
# xvfb-run needs to run the app on a machine without a display).
IMPETUS_PACKAGES=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev nlohmann-json3-dev libgtest-dev libgmock-dev
  qt6-base-dev qt6-charts-dev libqt6opengl6-dev libqt6svg6 qt6-l10n-tools qt6-tools-dev fonts-dejavu-core
  doxygen xvfb xauth
)

# What scripts/fuzz needs besides the engine's build tools and libraries: clang 14 and its
# libFuzzer. Not part of IMPETUS_PACKAGES: neither the app nor the test suite needs them.
IMPETUS_FUZZ_PACKAGES=(
  cmake ninja-build g++ libeigen3-dev nlohmann-json3-dev clang-14 libfuzzer-14-dev
)

impetus_install_packages() {
  local missing=()
  local pkg
  for pkg in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$pkg")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "impetus: installing missing Debian packages: ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null 2>&1; then
      echo "impetus: these packages are missing and sudo is not available: ${missing[*]}" >&2
      echo "impetus: install them as root, then run this script again." >&2
      exit 1
    fi
    sudo=(sudo)
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

impetus_setup() {
  impetus_install_packages "${IMPETUS_PACKAGES[@]}"
  cd "$IMPETUS_ROOT"
  cmake --preset release
  cmake --build --preset release -j "$(nproc)"
}
