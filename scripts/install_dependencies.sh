#!/usr/bin/env bash
# Installs, from Debian's packages, whatever the build needs and is missing,
# and the further packages given as arguments; --python adds what the Python
# package needs to build (pip install --no-build-isolation .), run and test.
set -euo pipefail
packages=(g++ make cmake libcgal-dev libeigen3-dev libboost-dev libboost-program-options-dev libtbb-dev catch2)
for argument in "$@"; do
  if [ "$argument" = --python ]; then
    packages+=(python3-dev python3-venv python3-pip python3-setuptools python3-wheel python3-numpy
               python3-pybind11 pybind11-dev python3-tqdm python3-open3d python3-pytest python3-distributed
               python3-matplotlib)
  else
    packages+=("$argument")
  fi
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
fi
