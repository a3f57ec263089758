#!/usr/bin/env bash
# Installs the Debian 12 packages ksmc needs (non-interactive). Uses sudo when not root.
# bc, procps, strace: the bad-input and signal tests (timings, pgrep, fault injection);
# chromium: the report.html browser test; ros-core ... librosbag-dev: the ROS nodes (ros/).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PACKAGES=(
  build-essential cmake pkg-config lld
  antlr4 libantlr4-runtime-dev
  libeigen3-dev libopencv-dev libpcl-dev libopenmpi-dev
  libfmt-dev catch2 nlohmann-json3-dev libcli11-dev libyaml-cpp-dev libtbb-dev
  libbullet-dev graphviz
  bc procps strace
  clang libclang-rt-14-dev
  chromium
  ros-core libroscpp-dev libnav-msgs-dev libvisualization-msgs-dev libstd-msgs-dev libsensor-msgs-dev librosbag-dev
)
missing=()
for p in "${PACKAGES[@]}"; do
  [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" == *"install ok installed"* ]] || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} Debian packages already installed"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
