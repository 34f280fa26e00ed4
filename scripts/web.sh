#!/usr/bin/env bash
# The harbor in a web page, checked in headless Chromium.
#
#   scripts/web.sh            # build out/web/, serve it, check it, screenshot out/web.png
#   scripts/web.sh --build    # build out/web/ only (no browser)
#   scripts/web.sh --serve    # build, then serve on http://127.0.0.1:8765/ until interrupted
#   scripts/web.sh --record   # check, then write the figures into benches/RESULTS.md
#
# Builds the harbor example for wasm32-unknown-unknown (feature `web`: WebGL2, bevy_rapier3d),
# binds it with wasm-bindgen-cli (the version of the wasm-bindgen crate in the lock file),
# shrinks it with wasm-opt -Oz (binaryen 116, from the wasm-opt crate: Debian's binaryen 108
# breaks the externref table rustc's wasm32 target now emits), and copies web/index.html and
# the bunny's OBJ (from the sample meshes, when present) beside it. What is missing is
# installed: the wasm32 target, both tools (with cargo, into ~/.cargo/bin) and, for the check,
# Debian's chromium.
# The check opens the page in calm water (?hs=0), waits for 20 s of physics, and fails if a
# body is not finite, is more than 1 cm off its theoretical draft, or the console has an error;
# it prints the frame time and the physics steps' share of it, and writes out/web.png.
#
# Size: the budget is 15 MB, and the wasm is over it (benches/RESULTS.md, "The harbor in a web
# page", says by how much and where its code comes from); the script fails beyond a ceiling
# of 17 MB, so that the size cannot grow unnoticed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
mode=${1:-check}
case $mode in
    check | --build | --serve | --record) ;;
    *) echo "usage: scripts/web.sh [--build | --serve | --record]" >&2; exit 2 ;;
esac
out=$root/out/web
crate=$root/crates/buoyancy-bevy
toolchain=$(sed -n 's/^channel *= *"\(.*\)"/\1/p' "$crate/rust-toolchain.toml")

rustup toolchain install "$toolchain" --profile minimal --target wasm32-unknown-unknown >/dev/null
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' "$crate/Cargo.lock")
bin=${CARGO_HOME:-$HOME/.cargo}/bin
if [ "$("$bin/wasm-bindgen" --version 2>/dev/null | awk '{print $2}')" != "$version" ]; then
    echo "== installing wasm-bindgen-cli $version"
    cargo "+$toolchain" install wasm-bindgen-cli --version "$version"
fi
wasm_opt=$bin/wasm-opt
if [ "$("$wasm_opt" --version 2>/dev/null | awk '{print $3}')" != 116 ]; then
    echo "== installing wasm-opt (binaryen 116)"
    cargo "+$toolchain" install wasm-opt --version 0.116.1
fi

echo "== building the harbor for wasm32-unknown-unknown"
(cd "$crate" && cargo build --profile web --example harbor --target wasm32-unknown-unknown --features rapier,web)
wasm=$crate/target/wasm32-unknown-unknown/web/examples/harbor.wasm
mkdir -p "$root/out"
report=$root/out/web-report.md
python3 scripts/wasm_size.py "$wasm" | tee "$report.sizes"
rm -rf "$out" && mkdir -p "$out"
"$bin/wasm-bindgen" --target web --no-typescript --remove-name-section --remove-producers-section \
    --out-dir "$out" --out-name harbor "$wasm"
echo "== wasm-opt -Oz"
mv "$out/harbor_bg.wasm" "$out/harbor_bg.unopt.wasm"
"$wasm_opt" -Oz --enable-reference-types --enable-bulk-memory --enable-nontrapping-float-to-int \
    --enable-sign-ext --enable-mutable-globals --enable-multivalue \
    "$out/harbor_bg.unopt.wasm" -o "$out/harbor_bg.wasm"
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
unoptimized=$(stat -c %s "$out/harbor_bg.unopt.wasm")
rm "$out/harbor_bg.unopt.wasm"
megabytes() { awk -v s="$1" 'BEGIN { printf "%.2f MB", s / 1e6 }'; }
gzipped=$(gzip -9 -c "$out/harbor_bg.wasm" | wc -c)
sizes="The wasm: $(megabytes "$unoptimized") from wasm-bindgen, $(megabytes "$size") after wasm-opt -Oz \
($(megabytes "$gzipped") gzipped); budget 15 MB$([ "$size" -gt 15000000 ] && echo \
", over it by $(megabytes $((size - 15000000)))"), ceiling 17 MB."
echo "== $sizes"
over_ceiling() {
    if [ "$size" -gt 17000000 ]; then
        echo "error: the wasm is over its 17 MB ceiling" >&2
        return 0
    fi
    return 1
}
if [ "$mode" = --build ]; then
    over_ceiling && exit 1
    exit 0
fi

if ! command -v chromium >/dev/null; then
    echo "== installing Debian's chromium"
    apt-get update -qq && apt-get install -y -qq chromium
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
python3 -u scripts/web_check.py "http://127.0.0.1:$port/?hs=0" --seconds 20 \
    --screenshot "$root/out/web.png" --summary "$report.check"
{
    echo "Machine: $(nproc) cores; $(chromium --version 2>/dev/null | head -1), headless, WebGL2 through SwiftShader; release profile \`web\` (opt-level z, fat LTO)."
    echo
    echo "$sizes"
    echo
    cat "$report.sizes"
    echo
    cat "$report.check"
} >"$report"
rm "$report.sizes" "$report.check"
echo "== wrote $report"
if [ "$mode" = --record ]; then
    python3 - "$report" benches/RESULTS.md <<'PY'
import sys
from pathlib import Path

report, results = Path(sys.argv[1]).read_text(), Path(sys.argv[2])
begin = "<!-- web-page:begin (written by `bash scripts/web.sh --record`) -->"
end = "<!-- web-page:end -->"
text = results.read_text()
block = f"{begin}\n{report.strip()}\n{end}"
if begin in text:
    head, rest = text.split(begin, 1)
    text = head + block + rest.split(end, 1)[1]
else:
    text = text.rstrip() + "\n\n## The harbor in a web page\n\n" + block + "\n"
results.write_text(text)
print(f"== wrote {results}")
PY
fi
over_ceiling && exit 1
exit 0
