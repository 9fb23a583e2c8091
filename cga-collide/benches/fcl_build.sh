# Shared by fcl_scene.sh and fcl_shapes.sh (sourced, not run): the work folder and the build of
# a small C++ driver against FCL (Debian's libfcl-dev, FCL 0.7; pkg-config when it knows fcl).
# After sourcing: $work is KEEP (created) or a temporary folder removed on exit;
# `build_fcl_driver SOURCE.cpp OUTPUT` compiles a driver with -O3.
if [ -n "${KEEP:-}" ]; then
  work="$KEEP"
  mkdir -p "$work"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
build_fcl_driver() {
  local cflags libs
  if pkg-config --exists fcl 2>/dev/null; then
    # pkg-config's own -std=c++11 comes first so that -std=c++17 wins.
    cflags="$(pkg-config --cflags fcl)"
    libs="$(pkg-config --libs fcl)"
  else
    cflags="-I/usr/include/eigen3"
    libs="-lfcl -lccd -lm"
  fi
  # shellcheck disable=SC2086
  g++ -O3 -DNDEBUG $cflags -std=c++17 "$1" -o "$2" $libs
}
