# Shared by scripts/start and scripts/test: install what is missing, configure and build.
# Sourced, not run. Everything comes from Debian/Ubuntu packages; nothing is downloaded at build
# time.

GLOSS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
GLOSS_JOBS="${GLOSS_JOBS:-$(nproc)}"

# Debian 12 / Ubuntu package names (third_party/README.md says what each is for).
GLOSS_PACKAGES=(
  cmake g++ clang libglfw3-dev libimgui-dev libglm-dev python3-glad libstb-dev
  libassimp-dev assimp-testmodels libembree-dev libtbb-dev nlohmann-json3-dev libcli11-dev libpng-dev
  libopenexr-dev libboost-dev libgtest-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri libegl-dev libclang-rt-14-dev
  imagemagick xdotool python3-matplotlib desktop-file-utils
)

gloss_log() { printf '[gloss] %s\n' "$*" >&2; }

# Installs only the packages that are not installed yet (a warm machine starts at once).
gloss_install_missing() {
  local missing=()
  for p in "${GLOSS_PACKAGES[@]}"; do
    dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    gloss_log "all ${#GLOSS_PACKAGES[@]} packages present"
    return 0
  fi
  gloss_log "installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}

# gloss_build DIR [cmake options...]: configure (once) and build.
gloss_build() {
  local dir="$1"
  shift
  cmake -S "$GLOSS_ROOT" -B "$GLOSS_ROOT/$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  cmake --build "$GLOSS_ROOT/$dir" -j "$GLOSS_JOBS"
}
