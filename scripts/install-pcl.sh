#!/usr/bin/env bash
# Installs PCL 1.13 (Debian 12's libpcl-dev) for the filters-vs-PCL peer benchmark only; the
# project itself does not depend on PCL.
set -euo pipefail
if dpkg-query -W -f='${Status}' libpcl-dev 2>/dev/null | grep -q "install ok installed"; then exit 0; fi
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends libpcl-dev
