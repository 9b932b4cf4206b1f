#!/usr/bin/env bash
# Installs the Debian packages given that are missing (a no-op when all are present), as root
# or through sudo. Used by make deps, make bench and make fuzz.
#   scripts/ci/install_debian_packages.sh TARGET PACKAGE...
set -euo pipefail
target=$1; shift
missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep >/dev/null 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "make $target: installing ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
"${sudo[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
