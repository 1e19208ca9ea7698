#!/usr/bin/env bash
# Installs what conecurl needs on Debian 12, and only what is missing: running it again does nothing.
# A user's emsdk (em++ already on PATH) is used as is; then Debian's emscripten is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."

have_cmd() { command -v "$1" >/dev/null 2>&1; }
have_pkg() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'install ok installed'; }

missing=()
have_cmd em++ || missing+=(emscripten)
[ -f /usr/include/glm/glm.hpp ] || [ -f /usr/local/include/glm/glm.hpp ] || missing+=(libglm-dev)
have_cmd chromium || [ -n "${CHROMIUM_PATH:-}" ] || missing+=(chromium)
have_pkg fonts-dejavu-core || missing+=(fonts-dejavu-core)  # text in the demo and test pages
have_cmd cmake || missing+=(cmake)
have_cmd g++ || missing+=(g++)
have_cmd make || missing+=(make)
{ have_pkg libgtest-dev || [ -f /usr/include/gtest/gtest.h ]; } || missing+=(googletest libgtest-dev)
have_cmd node || missing+=(nodejs)
have_cmd npm || missing+=(npm)

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if have_cmd sudo; then sudo="sudo"; else
      echo "setup: these Debian packages are missing and we are not root: ${missing[*]}" >&2
      echo "setup: install them (apt-get install ${missing[*]}) and run again" >&2
      exit 1
    fi
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# npm ci only when node_modules is missing or older than the lock file.
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "setup: npm ci"
  npm ci --no-audit --no-fund --loglevel=error
fi
