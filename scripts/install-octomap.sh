#!/usr/bin/env bash
# Installs OctoMap 1.9 (Debian 12's liboctomap-dev) for the occupancy-vs-OctoMap peer benchmark
# only (tests/bench/occupancy_vs_octomap_bench.cpp); the project itself does not depend on it.
set -euo pipefail
if dpkg-query -W -f='${Status}' liboctomap-dev 2>/dev/null | grep -q "install ok installed"; then exit 0; fi
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends liboctomap-dev
