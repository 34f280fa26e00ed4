"""Where the sample meshes are: the models of the paper's performance table (``bunny.obj``,
``armadillo.obj``, ``torusknot.obj``, …), which are not shipped with the package.

They are looked for in the folder named by ``$BUOYANCY_MESHES``, else in ``../shared/meshes``
beside the repository. The tests, the benchmarks and ``examples/float_rapier.py`` use this one
helper, passing the repository's root.

>>> import pathlib, tempfile
>>> from buoyancy._sample_meshes import find_sample_mesh, not_found_message, sample_meshes_dir
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> repository = root / "buoyancy"
>>> sample_meshes_dir(repository, environ={}) == root / "shared" / "meshes"
True
>>> find_sample_mesh("bunny.obj", repository, environ={}) is None  # nothing there
True
>>> print(not_found_message(repository, "bunny.obj", environ={}))  # doctest: +ELLIPSIS
bunny.obj not found in .../shared/meshes (../shared/meshes beside the repository; set BUOYANCY_MESHES to the folder of the sample meshes to look elsewhere)
"""

from __future__ import annotations

import os
import pathlib
from collections.abc import Mapping

__all__ = ["ENVIRONMENT_VARIABLE", "find_sample_mesh", "not_found_message", "sample_meshes_dir"]

#: The environment variable naming the folder of the sample meshes.
ENVIRONMENT_VARIABLE = "BUOYANCY_MESHES"


def sample_meshes_dir(repository: str | os.PathLike[str], environ: Mapping[str, str] | None = None) -> pathlib.Path:
    """The folder the sample meshes are looked for in (it may not exist):
    ``$BUOYANCY_MESHES`` if set and not empty, else ``../shared/meshes`` beside ``repository``.

    ``environ`` defaults to ``os.environ``.
    """
    env = (os.environ if environ is None else environ).get(ENVIRONMENT_VARIABLE)
    if env:
        return pathlib.Path(env)
    return pathlib.Path(repository).resolve().parent / "shared" / "meshes"


def find_sample_mesh(
    name: str, repository: str | os.PathLike[str], environ: Mapping[str, str] | None = None
) -> pathlib.Path | None:
    """The path of the sample mesh file ``name`` (e.g. ``"bunny.obj"``), or ``None`` if it is
    not in :func:`sample_meshes_dir`."""
    path = sample_meshes_dir(repository, environ) / name
    return path if path.is_file() else None


def not_found_message(
    repository: str | os.PathLike[str], name: str | None = None, environ: Mapping[str, str] | None = None
) -> str:
    """What to print when a sample mesh (``name``; the folder itself when ``None``) is missing:
    where it was looked for, and how to look elsewhere."""
    env = (os.environ if environ is None else environ).get(ENVIRONMENT_VARIABLE)
    folder = sample_meshes_dir(repository, environ)
    what = f"{name} not found in {folder}" if name else f"the sample meshes' folder {folder} not found"
    if env:
        return f"{what} (named by ${ENVIRONMENT_VARIABLE})"
    return (
        f"{what} (../shared/meshes beside the repository; set {ENVIRONMENT_VARIABLE} to the folder "
        "of the sample meshes to look elsewhere)"
    )
