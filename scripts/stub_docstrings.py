"""The docstrings of the hand-written stub ``python/buoyancy/_core.pyi``, written from the
compiled module, so that they cannot drift from the Rust doc comments they come from.

The signatures in the stub are written by hand (and checked by ``python -m mypy.stubtest
buoyancy._core``); every docstring in it is the compiled module's own: for each public class,
method, property and function the stub declares, its ``__doc__`` (cleaned as ``inspect.getdoc``
does), or no docstring where the module has none. Overloads and dunder methods keep what the
stub says.

    python scripts/stub_docstrings.py           # rewrite the stub's docstrings
    python scripts/stub_docstrings.py --check   # exit 1, with a diff, if the stub has drifted

Run it with the wheel built from this tree and ruff installed (``pip install '.[test]'``);
``tests/python/test_api.py`` runs the check.
"""

from __future__ import annotations

import argparse
import ast
import difflib
import inspect
import pathlib
import subprocess
import sys
from types import ModuleType

STUB = pathlib.Path(__file__).resolve().parents[1] / "python" / "buoyancy" / "_core.pyi"


def literal(doc: str, indent: str) -> list[str]:
    """``doc`` as the lines of a triple-quoted docstring at ``indent`` (raw when it holds a
    backslash), each line of ``doc`` after the first indented."""
    if '"""' in doc:
        raise ValueError(f'a docstring holds """: {doc[:60]!r}')
    prefix = "r" if "\\" in doc else ""
    lines = doc.split("\n")
    if len(lines) == 1:
        return [f'{indent}{prefix}"""{doc}"""']
    body = [f"{indent}{line}" if line.strip() else "" for line in lines[1:]]
    return [f'{indent}{prefix}"""{lines[0]}', *body, f'{indent}"""']


def runtime_doc(obj: object) -> str | None:
    """The docstring ``obj`` has at run time, cleaned, or ``None``."""
    doc = inspect.getdoc(obj)
    return doc if doc else None


def declared(tree: ast.Module, module: ModuleType) -> list[tuple[ast.AST, str | None]]:
    """The stub's public classes, methods, properties and functions with the docstrings their
    compiled counterparts have; those the module lacks are left out."""
    found: list[tuple[ast.AST, str | None]] = []

    def visit(body: list[ast.stmt], owner: object) -> None:
        for node in body:
            if not isinstance(node, (ast.ClassDef, ast.FunctionDef)):
                continue
            if node.name.startswith("_") or not hasattr(owner, node.name):
                continue
            decorators = {d.id for d in node.decorator_list if isinstance(d, ast.Name)}
            if "overload" in decorators:
                continue
            obj = inspect.getattr_static(owner, node.name)
            if isinstance(obj, (classmethod, staticmethod)):
                obj = obj.__func__
            found.append((node, runtime_doc(obj)))
            if isinstance(node, ast.ClassDef):
                visit(node.body, getattr(owner, node.name))

    visit(tree.body, module)
    return found


def render(stub: str, module: ModuleType) -> str:
    """``stub`` with each declared item's docstring replaced by the compiled module's."""
    tree = ast.parse(stub)
    lines = stub.split("\n")
    # Bottom up, so that the line numbers of the items not yet edited hold.
    items = sorted(declared(tree, module), key=lambda item: item[0].lineno, reverse=True)
    for node, doc in items:
        assert isinstance(node, (ast.ClassDef, ast.FunctionDef))
        first = node.body[0]
        has_doc = (
            isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str)
        )
        rest = node.body[1:] if has_doc else node.body
        only_ellipsis = (
            len(rest) == 1
            and isinstance(rest[0], ast.Expr)
            and isinstance(rest[0].value, ast.Constant)
            and rest[0].value.value is Ellipsis
        )
        indent = " " * (node.col_offset + 4)
        if has_doc:
            start, end = first.lineno - 1, first.end_lineno or first.lineno
            new = literal(doc, indent) if doc is not None else []
            if doc is None and not rest:
                # The docstring was the whole body: an ellipsis instead, on the signature's line.
                lines[start - 1] = lines[start - 1].rstrip() + " ..."
            lines[start:end] = new
        elif doc is not None:
            if rest and not only_ellipsis:
                position = rest[0].lineno - 1
                lines[position:position] = literal(doc, indent)
            else:
                # `def f(...) -> T: ...` on one line, or a body of a lone `...`: the docstring
                # becomes the body.
                ellipsis = rest[0]
                row = ellipsis.lineno - 1
                line = lines[row]
                head = line[: ellipsis.col_offset].rstrip()
                if head:  # the ellipsis follows the signature on its line
                    lines[row : row + 1] = [head, *literal(doc, indent)]
                else:
                    lines[row : row + 1] = literal(doc, indent)
    return formatted("\n".join(lines))


def formatted(stub: str) -> str:
    """``stub`` as ``ruff format`` writes it (the blank lines a multi-line item needs), so that
    the stub passes the formatter's check; ruff is configured in ``pyproject.toml``."""
    result = subprocess.run(
        [sys.executable, "-m", "ruff", "format", "--stdin-filename", str(STUB), "-"],
        input=stub,
        capture_output=True,
        text=True,
        check=False,
    )
    if result.returncode != 0:
        raise RuntimeError(f"ruff format failed (pip install 'ruff~=0.17.6'): {result.stderr.strip()}")
    return result.stdout


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="exit 1, with a diff, if the stub has drifted")
    args = parser.parse_args(argv)
    import buoyancy._core as module

    stub = STUB.read_text(encoding="utf-8")
    rendered = render(stub, module)
    if args.check:
        if rendered == stub:
            print(f"{STUB.name}: its docstrings are the compiled module's")
            return 0
        diff = difflib.unified_diff(
            stub.splitlines(), rendered.splitlines(), f"{STUB.name} (as written)", f"{STUB.name} (from the module)", n=1
        )
        print("\n".join(diff))
        print(f"{STUB.name}: docstrings differ from the compiled module's; run python scripts/stub_docstrings.py")
        return 1
    STUB.write_text(rendered, encoding="utf-8")
    print(f"wrote {STUB}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
