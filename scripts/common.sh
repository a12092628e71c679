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
  imagemagick xdotool python3-matplotlib desktop-file-utils nodejs
)

# npm packages, installed globally (npm root -g) after the Debian ones: the Khronos
# glTF-Validator, which tests/export/validate_exports.cmake runs with node on gloss-cli's glTF
# exports. Pinned so every machine validates alike.
GLOSS_NPM_PACKAGES=(gltf-validator@2.0.0-dev.3.10)

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

# Installs GLOSS_NPM_PACKAGES that node cannot find yet. Debian's nodejs comes without npm (its
# `npm` package); NodeSource's nodejs brings its own, so npm is installed only when missing.
gloss_install_npm_missing() {
  command -v node >/dev/null || return 0
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  if ! command -v npm >/dev/null; then
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends npm \
      >/dev/null
  fi
  local root
  root="$(npm root -g)"
  for p in "${GLOSS_NPM_PACKAGES[@]}"; do
    if ! NODE_PATH="$root" node -e "require.resolve('${p%@*}')" >/dev/null 2>&1; then
      gloss_log "installing npm package $p"
      $sudo npm install -g --no-fund --no-audit "$p" >/dev/null
    fi
  done
}

# gloss_build DIR [cmake options...]: configure (once) and build.
gloss_build() {
  local dir="$1"
  shift
  cmake -S "$GLOSS_ROOT" -B "$GLOSS_ROOT/$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  cmake --build "$GLOSS_ROOT/$dir" -j "$GLOSS_JOBS"
}
