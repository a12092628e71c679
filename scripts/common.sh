# Shared by scripts/start and scripts/test: install what is missing, configure and build.
# Sourced, not run. Everything comes from Debian/Ubuntu packages; nothing is downloaded at build
# time.

GLOSS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
GLOSS_JOBS="${GLOSS_JOBS:-$(nproc)}"

# Debian 12 / Ubuntu package names (third_party/README.md says what each is for).
GLOSS_PACKAGES=(
  cmake g++ clang libglfw3-dev libimgui-dev libglm-dev python3-glad libstb-dev
  libassimp-dev assimp-testmodels libembree-dev libtbb-dev nlohmann-json3-dev libcli11-dev libpng-dev
  libjpeg-dev libopenexr-dev libboost-dev libgtest-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri libegl-dev libclang-rt-14-dev
  imagemagick xdotool python3-matplotlib desktop-file-utils nodejs curl
)

# The Khronos glTF-Validator (npm package gltf-validator: one package, no dependencies), which
# tests/export/validate_exports.cmake runs with node on gloss-cli's glTF exports. Pinned, with the
# registry's SHA-1 of its tarball, so every machine validates alike.
GLOSS_GLTF_VALIDATOR_VERSION=2.0.0-dev.3.10
GLOSS_GLTF_VALIDATOR_SHA1=9b09225db864fe3f0a584259f65d087e2213a93a
# Where it goes when npm is not there (the test looks here too).
GLOSS_NODE_MODULES="${GLOSS_NODE_MODULES:-$HOME/.cache/gloss/node_modules}"

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

# Makes the glTF-Validator available to node, or says plainly why not; it never stops the
# set-up (the validator test then says SKIPPED with the reason). Debian 12's npm package pulls
# about 355 packages (22.6 MB) into a machine that has node, so npm is not installed: with npm
# already there (NodeSource's nodejs brings it) `npm install -g`, else the one tarball fetched
# from the npm registry with curl, checked against its SHA-1 and unpacked into GLOSS_NODE_MODULES.
gloss_install_gltf_validator() {
  if ! command -v node >/dev/null; then
    gloss_log "warning: node not found: the glTF validator test will be skipped"
    return 0
  fi
  local paths="$GLOSS_NODE_MODULES:/usr/lib/node_modules:/usr/local/lib/node_modules"
  command -v npm >/dev/null && paths="$(npm root -g):$paths"
  if NODE_PATH="$paths" node -e "require.resolve('gltf-validator')" >/dev/null 2>&1; then
    return 0
  fi
  local name="gltf-validator@$GLOSS_GLTF_VALIDATOR_VERSION"
  gloss_log "installing $name"
  if command -v npm >/dev/null; then
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    if ! timeout 300 $sudo npm install -g --no-fund --no-audit --fetch-retries=1 \
      --fetch-timeout=60000 "$name" >/dev/null 2>&1; then
      gloss_log "warning: npm could not install $name (registry unreachable?):" \
        "the glTF validator test will be skipped"
    fi
    return 0
  fi
  local url="https://registry.npmjs.org/gltf-validator/-/gltf-validator-$GLOSS_GLTF_VALIDATOR_VERSION.tgz"
  local tmp
  tmp="$(mktemp -d)"
  if curl -fsSL --max-time 120 -o "$tmp/v.tgz" "$url" &&
    echo "$GLOSS_GLTF_VALIDATOR_SHA1  $tmp/v.tgz" | sha1sum -c --status &&
    mkdir -p "$tmp/x" && tar -xzf "$tmp/v.tgz" -C "$tmp/x"; then
    mkdir -p "$GLOSS_NODE_MODULES"
    rm -rf "$GLOSS_NODE_MODULES/gltf-validator"
    mv "$tmp/x/package" "$GLOSS_NODE_MODULES/gltf-validator"
  else
    gloss_log "warning: could not fetch $url (registry unreachable, or its SHA-1 differs):" \
      "the glTF validator test will be skipped"
  fi
  rm -rf "$tmp"
  return 0
}

# gloss_build DIR [cmake options...]: configure (once) and build.
gloss_build() {
  local dir="$1"
  shift
  cmake -S "$GLOSS_ROOT" -B "$GLOSS_ROOT/$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  cmake --build "$GLOSS_ROOT/$dir" -j "$GLOSS_JOBS"
}
