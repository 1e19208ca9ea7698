#!/usr/bin/env bash
# Installs what conecurl needs on Debian 12, and only what is missing: running it again does nothing.
# Every check looks at what is really there (an executable on PATH, a header or font file, an
# installed Debian package), never at a variable another script filled in with a guess.
#
#   bash scripts/setup.sh          install what is missing (apt-get, then npm ci)
#   bash scripts/setup.sh --plan   print the steps it would take, one per line, and change nothing:
#                                  "apt-get install PKG..." and/or "npm ci"; nothing when all is there
#   bash scripts/setup.sh --bench  (with or without --plan) also what `npm run bench` alone needs: the
#                                  tools publish-rate.mjs measures conecurl publish against (poppler's
#                                  pdftoppm, MuPDF's mutool, cwebp)
#
# A user's emsdk (em++ already on PATH) is used as is; then Debian's emscripten is not installed.
# CHROMIUM_PATH, when set, must name an executable file; otherwise `chromium` must be on PATH.
# SETUP_ROOT (tests only) is the directory under which headers and fonts are looked for.
# Uses only bash builtins until it installs, so the plan runs with a PATH that holds nothing else.
set -euo pipefail
here=${BASH_SOURCE[0]%/*}
[ "$here" = "${BASH_SOURCE[0]}" ] && here=.
cd "$here/.."
root=${SETUP_ROOT:-}

plan=0
bench=0
for arg in "$@"; do
  case "$arg" in
    --plan) plan=1 ;;
    --bench) bench=1 ;;
    *) echo "setup: unknown argument '$arg' (use --plan to print what would be installed, --bench to add the benchmark's tools)" >&2; exit 2 ;;
  esac
done

have_cmd() { command -v "$1" >/dev/null 2>&1; }
have_file() { local f; for f in "$@"; do [ -f "$root$f" ] && return 0; done; return 1; }
have_pkg() {
  local status
  status=$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null) || return 1
  [[ $status == *"install ok installed"* ]]
}
have_chromium() {
  if [ -n "${CHROMIUM_PATH:-}" ]; then
    [ -f "$CHROMIUM_PATH" ] && [ -x "$CHROMIUM_PATH" ] && return 0
    echo "setup: CHROMIUM_PATH=$CHROMIUM_PATH is not an executable file; looking for chromium on PATH" >&2
  fi
  have_cmd chromium
}

missing=()
have_cmd em++ || missing+=(emscripten)
have_file /usr/include/glm/glm.hpp /usr/local/include/glm/glm.hpp || missing+=(libglm-dev)
have_chromium || missing+=(chromium)
# Text in the demo and test pages (reference images are drawn with it).
have_file /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf || have_pkg fonts-dejavu-core || missing+=(fonts-dejavu-core)
have_cmd cmake || missing+=(cmake)
have_cmd g++ || missing+=(g++)
have_cmd make || missing+=(make)
# CMake's find_package(GTest) needs the headers and the built libraries, both in libgtest-dev.
have_file /usr/include/gtest/gtest.h /usr/local/include/gtest/gtest.h || have_pkg libgtest-dev || missing+=(libgtest-dev)
# The cross-engine suite (tests/engines/): Firefox over WebDriver BiDi and WebKitGTK's MiniBrowser through
# WebKitWebDriver, each on an Xvfb display (WebGL2 needs one even headless); Firefox speaks through
# speech-dispatcher with espeak-ng (WebKit has voices of its own).
have_cmd firefox-esr || missing+=(firefox-esr)
have_cmd Xvfb || missing+=(xvfb)
have_cmd WebKitWebDriver || missing+=(webkit2gtk-driver)
have_file /usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser /usr/lib/aarch64-linux-gnu/webkit2gtk-4.1/MiniBrowser \
  || missing+=(libwebkit2gtk-4.1-0)
have_cmd speech-dispatcher || missing+=(speech-dispatcher)
have_cmd espeak-ng || missing+=(espeak-ng)
have_cmd node || missing+=(nodejs)
have_cmd npm || missing+=(npm)
if [ $bench -eq 1 ]; then
  # The roads scripts/bench/publish-rate.mjs measures `conecurl publish` against.
  have_cmd pdftoppm || missing+=(poppler-utils)
  have_cmd mutool || missing+=(mupdf-tools)
  have_cmd cwebp || missing+=(webp)
fi

# npm ci only when node_modules is missing or older than the lock file.
need_npm_ci=0
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  need_npm_ci=1
fi

if [ $plan -eq 1 ]; then
  [ ${#missing[@]} -eq 0 ] || echo "apt-get install ${missing[*]}"
  [ $need_npm_ci -eq 0 ] || echo "npm ci"
  exit 0
fi

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
  # What apt-get said it installed must now be there: a package that installs under another name
  # would otherwise pass here and fail later in a build or a browser test.
  still=$(SETUP_ROOT="$root" bash scripts/setup.sh --plan "$@" | { grep '^apt-get' || true; })
  if [ -n "$still" ]; then
    echo "setup: still missing after apt-get: ${still#apt-get install }" >&2
    exit 1
  fi
fi

if [ $need_npm_ci -eq 1 ]; then
  echo "setup: npm ci"
  npm ci --no-audit --no-fund --loglevel=error
fi
