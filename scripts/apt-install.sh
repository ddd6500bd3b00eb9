#!/usr/bin/env bash
# Installs the Debian packages named on the command line that are not installed yet (the one
# installer behind scripts/install-deps.sh and scripts/install-test-deps.sh, which hold the lists).
# Idempotent: quiet and fast when everything is already installed. LFD_APT_LABEL names the list
# in its two lines of output.
set -euo pipefail
label="${LFD_APT_LABEL:-apt-install}"
missing=()
for p in "$@"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "$label: installing ${#missing[@]} package(s): ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "$label: done"
