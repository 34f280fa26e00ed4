#!/usr/bin/env python3
"""Where the code of a WebAssembly module comes from, by crate group.

    python3 scripts/wasm_size.py crates/buoyancy-bevy/target/wasm32-unknown-unknown/web/examples/harbor.wasm

Reads the module's ``name`` section (rustc's output has it; wasm-bindgen removes it in
scripts/web.sh), attributes each function body to the crate its mangled name starts in (a
generic function instantiated for another crate's types counts for the crate that defines
it), and prints a Markdown table of the code section's bytes by group. Standard library only.
"""

from __future__ import annotations

import re
import sys
from collections import Counter
from pathlib import Path

# The first crate a v0 or legacy mangled name names: `C<disambiguator>_<length><name>`.
CRATE = re.compile(r"C[s]?[0-9A-Za-z]*_(\d+)([A-Za-z_][A-Za-z0-9_]*)")

GROUPS = [
    ("buoyancy (core, rapier adapter, plugin, the harbor)", lambda c: c.startswith("buoyancy") or c == "harbor"),
    (
        "physics (rapier3d, parry3d, bevy_rapier3d, nalgebra)",
        lambda c: c in {"rapier3d", "parry3d", "bevy_rapier3d", "nalgebra", "simba"},
    ),
    ("bevy_ecs (systems, queries, components)", lambda c: c.startswith("bevy_ecs")),
    (
        "reflection and serialisation (bevy_reflect, erased_serde, ron, serde)",
        lambda c: c in {"bevy_reflect", "erased_serde", "ron", "serde", "serde_core", "inventory"},
    ),
    (
        "Bevy's renderer and app (bevy_*, wgpu, naga, wesl, winit)",
        lambda c: (
            c.startswith(("bevy", "wgpu")) or c in {"naga", "wgsl_parse", "wesl", "logos", "winit", "glow", "encase"}
        ),
    ),
    ("Rust's core, alloc and std, hashbrown", lambda c: c in {"core", "alloc", "std", "hashbrown"}),
]


def leb128(data: bytes, at: int) -> tuple[int, int]:
    """An unsigned LEB128 number at ``at``, and the offset after it."""
    value, shift = 0, 0
    while True:
        byte = data[at]
        at += 1
        value |= (byte & 0x7F) << shift
        shift += 7
        if byte < 0x80:
            return value, at


def function_sizes(data: bytes) -> tuple[list[int], dict[int, str], int]:
    """The code section's body sizes, the name section's function names and the import count."""
    if data[:4] != b"\0asm":
        raise ValueError("not a WebAssembly module")
    at, imported, bodies, names = 8, 0, [], {}
    while at < len(data):
        section = data[at]
        size, at = leb128(data, at + 1)
        end = at + size
        if section == 2:  # imports: count the functions
            count, i = leb128(data, at)
            for _ in range(count):
                for _ in range(2):  # module and field names
                    length, i = leb128(data, i)
                    i += length
                kind = data[i]
                i += 1
                if kind == 0:  # function: a type index
                    _, i = leb128(data, i)
                    imported += 1
                elif kind == 1:  # table: a reference type and limits
                    flags = data[i + 1]
                    _, i = leb128(data, i + 2)
                    if flags & 1:
                        _, i = leb128(data, i)
                elif kind == 2:  # memory: limits
                    flags = data[i]
                    _, i = leb128(data, i + 1)
                    if flags & 1:
                        _, i = leb128(data, i)
                elif kind == 3:  # global: a value type and mutability
                    i += 2
                else:
                    i += 1  # a tag: attribute and type index (one byte each here)
                    _, i = leb128(data, i)
        elif section == 10:  # code
            count, i = leb128(data, at)
            for _ in range(count):
                length, i = leb128(data, i)
                bodies.append(length)
                i += length
        elif section == 0:
            length, i = leb128(data, at)
            if data[i : i + length] == b"name":
                i += length
                while i < end:
                    kind = data[i]
                    length, i = leb128(data, i + 1)
                    if kind == 1:  # function names
                        count, j = leb128(data, i)
                        for _ in range(count):
                            index, j = leb128(data, j)
                            n, j = leb128(data, j)
                            names[index] = data[j : j + n].decode("utf-8", "replace")
                            j += n
                    i += length
        at = end
    return bodies, names, imported


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    bodies, names, imported = function_sizes(Path(sys.argv[1]).read_bytes())
    if not names:
        print("wasm_size: the module has no name section (stripped?)", file=sys.stderr)
        return 1
    groups: Counter[str] = Counter()
    for index, size in enumerate(bodies):
        match = CRATE.search(names.get(index + imported, ""))
        crate = match.group(2)[: int(match.group(1))] if match else ""
        group = next((name for name, member in GROUPS if member(crate)), "other")
        groups[group] += size
    total = sum(groups.values())
    print("| code by origin (before wasm-bindgen and wasm-opt) | MB | share |\n|---|---|---|")
    for group, size in groups.most_common():
        print(f"| {group} | {size / 1e6:.2f} | {100 * size / total:.0f} % |")
    print(f"| all | {total / 1e6:.2f} | 100 % |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
