#!/usr/bin/env bash
# The harbor in a web page, checked in headless Chromium.
#
#   scripts/web.sh            # build out/web/, serve it, check it, screenshot out/web.png
#   scripts/web.sh --build    # build out/web/ only (no browser)
#   scripts/web.sh --serve    # build, then serve on http://127.0.0.1:8765/ until interrupted
#
# Builds the harbor example for wasm32-unknown-unknown (feature `web`: WebGL2, bevy_rapier3d),
# binds it with wasm-bindgen-cli (the version of the wasm-bindgen crate in the lock file;
# installed with cargo if missing), and
# copies web/index.html and the bunny's OBJ (from the sample meshes, when present) beside it.
# The check opens the page in calm water (?hs=0), waits for 20 s of physics, and fails if a
# body is not finite, is more than 1 cm off its theoretical draft, or the console has an error.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
mode=${1:-check}
out=$root/out/web
crate=$root/crates/buoyancy-bevy
toolchain=$(sed -n 's/^channel *= *"\(.*\)"/\1/p' "$crate/rust-toolchain.toml")

rustup toolchain install "$toolchain" --profile minimal --target wasm32-unknown-unknown >/dev/null
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' "$crate/Cargo.lock")
if [ "$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')" != "$version" ]; then
    echo "== installing wasm-bindgen-cli $version"
    cargo "+$toolchain" install wasm-bindgen-cli --version "$version"
fi

echo "== building the harbor for wasm32-unknown-unknown"
(cd "$crate" && cargo build --profile web --example harbor --target wasm32-unknown-unknown --features rapier,web)
rm -rf "$out" && mkdir -p "$out"
wasm-bindgen --target web --no-typescript --out-dir "$out" --out-name harbor \
    "$crate/target/wasm32-unknown-unknown/web/examples/harbor.wasm"
# Debian's binaryen (wasm-opt 108) predates the reference types rustc's wasm32 target emits:
# its output fails in the browser (WebAssembly.Table.set on the externref table), so the wasm
# is served as wasm-bindgen leaves it.
cp web/index.html "$out/"
meshes=${BUOYANCY_MESHES:-$root/../shared/meshes}
if [ -f "$meshes/bunny.obj" ]; then
    cp "$meshes/bunny.obj" "$out/"
elif [ "${CI:-}" = true ]; then
    echo "error: the sample meshes are not at $meshes (set BUOYANCY_MESHES)" >&2
    exit 1
else
    echo "note: no bunny.obj at $meshes: the page floats without the bunny"
fi
size=$(stat -c %s "$out/harbor_bg.wasm")
echo "== out/web: harbor_bg.wasm $(awk -v s="$size" 'BEGIN { printf "%.2f MB", s / 1e6 }') (budget: 15 MB)"
over_budget() {
    if [ "$size" -gt 15000000 ]; then
        echo "error: the wasm is over the 15 MB budget" >&2
        return 0
    fi
    return 1
}
if [ "$mode" = --build ]; then
    over_budget && exit 1
    exit 0
fi

port=8765
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$out" >"$root/out/web-server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null' EXIT
sleep 1
if [ "$mode" = --serve ]; then
    echo "== serving http://127.0.0.1:$port/ (Ctrl-C to stop)"
    wait "$server"
fi
echo "== headless Chromium: http://127.0.0.1:$port/?hs=0"
python3 scripts/web_check.py "http://127.0.0.1:$port/?hs=0" --seconds 20 --screenshot "$root/out/web.png"
over_budget && exit 1
exit 0
