# Sourced by the build scripts: the toolchain quirks of Debian's emscripten 3.1.6 in one place.
# Its JS optimizer needs acorn from Debian's node modules; an emsdk brings its own and ignores this.
if [ -d /usr/share/nodejs ] && [ -z "${NODE_PATH:-}" ]; then
  export NODE_PATH=/usr/share/nodejs
fi
