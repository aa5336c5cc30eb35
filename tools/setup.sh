#!/usr/bin/env bash
# Installs the Debian packages tbridge needs to build, test and plot. Idempotent: packages
# already installed are left alone, and the package lists are refreshed only when something
# is missing. Tested on Debian 12 (bookworm).
set -euo pipefail

packages=(
  build-essential      # g++ 12, make
  cmake
  clang-format-14      # the formatter the tests hold every C++ file to (tools/check_format.sh)
  clang-tidy-14        # the function-size check the tests run (tools/check_function_size.sh)
  pkg-config           # finds Ipopt
  libeigen3-dev        # dense and sparse linear algebra
  coinor-libipopt-dev  # default minimum-mass solver
  libnlopt-cxx-dev     # second minimum-mass solver
  libsuitesparse-dev   # CHOLMOD, sparse factorisations in the dynamics
  libspectra-dev       # sparse Lanczos eigensolvers (lowest modes of large models)
  nlohmann-json3-dev   # JSON configs and outputs
  catch2               # unit tests (Catch2 v2)
  python3
  python3-matplotlib   # figures from the outputs
  python3-numpy        # the Python module's arrays
  python3-pytest       # the Python module's tests
  pybind11-dev         # builds the Python module
  calculix-ccx         # CalculiX, the FE program the export is tested against
  tcl                  # tclsh: runs the exported OpenSees scripts against a stand-in in the tests
  time                 # GNU time: peak memory of whole-process benchmarks
)

say() { echo "setup: $*"; }

if ! command -v dpkg-query > /dev/null 2>&1 || ! command -v apt-get > /dev/null 2>&1; then
  say "this script needs a Debian-based system (dpkg and apt-get); install by hand:"
  say "  ${packages[*]}"
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  if [ "$(dpkg-query -W -f='${Status}' "$p" 2> /dev/null || true)" = "install ok installed" ]; then
    say "$p is installed"
  else
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  say "all ${#packages[@]} packages are installed; nothing to do"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo > /dev/null 2>&1; then
    say "not root and sudo is not available; as root run:"
    say "  apt-get update && apt-get install -y ${missing[*]}"
    exit 1
  fi
  sudo_cmd=(sudo)
fi

export DEBIAN_FRONTEND=noninteractive
say "missing: ${missing[*]}"
say "running: ${sudo_cmd[*]:+${sudo_cmd[*]} }apt-get update"
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
say "running: ${sudo_cmd[*]:+${sudo_cmd[*]} }apt-get install -y --no-install-recommends ${missing[*]}"
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
say "done"
