#!/usr/bin/env bash
# Installs the Debian packages ncverify needs, the npm packages of its HTML report (pinned in
# package-lock.json: three.js and esbuild for the build, chrome-remote-interface and pngjs
# for the browser test) and builds it (Release) into build/.
# Idempotent: packages already present are not reinstalled; the build is incremental.
# Usage: scripts/setup.sh [--no-build]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config git
  libopenmesh-dev libcli11-dev libspdlog-dev libfmt-dev catch2 libtbb-dev jq
  nlohmann-json3-dev libxxhash-dev libbenchmark-dev libembree-dev
  clang lld libclang-rt-14-dev clang-format python3 python3-numpy time
  chromium
  slurm-wlm munge parallel
)
# Node.js and npm from Debian, unless some node is installed already (its npm comes with it).
command -v node >/dev/null && command -v npm >/dev/null || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  echo "setup: installing ${missing[*]}" >&2
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

# npm ci installs exactly the locked versions (and never a browser: the test drives Debian's
# chromium); it runs again only when the lock file changed.
if ! cmp -s package-lock.json node_modules/.ncverify-installed-lock 2>/dev/null; then
  echo "setup: npm ci" >&2
  npm ci --no-audit --no-fund --loglevel=error >&2
  cp package-lock.json node_modules/.ncverify-installed-lock
fi

if [ "${1:-}" != "--no-build" ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
  cmake --build build >&2
fi
