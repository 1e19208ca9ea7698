#!/usr/bin/env bash
# Builds and runs the native GoogleTest suite through CTest, plainly and under ASan + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
for variant in native native-sanitized; do
  flags=(-DCMAKE_BUILD_TYPE=Release)
  [ "$variant" = native-sanitized ] && flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCONECURL_SANITIZE=ON)
  [ -f "build/$variant/CMakeCache.txt" ] || cmake -S . -B "build/$variant" "${flags[@]}" >/dev/null
  cmake --build "build/$variant" -j2
  echo "ctest variant: $variant"
  (cd "build/$variant" && ctest --output-on-failure)
done
