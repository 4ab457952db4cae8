# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Point files read by parts and written whole, for ``cgal_rrht.tiles``.

Binary PLY (as ``rrht_normals`` writes it) and ``.npy`` files are memory-mapped,
so that a task reads the points of a neighboring tile that it needs without
holding the whole tile (Open3D and NumPy's text readers load whole files).
LAS files are read by record ranges with the reader of ``rrht_normals``
(``CGAL::RRHT::IO::LAS_file``, bound as ``cgal_rrht._core.LASFile``).
Text files (``.xyz``, ``.pwn``, ASCII PLY and ``.off``, the other files that
``rrht_normals`` reads) are read in chunks of rows. Files are written
through a temporary file renamed at the end, so that a failed write never
leaves a partial file in place of a good one.
"""

from __future__ import annotations

import os
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

from ._core import LASError, LASFile

__all__ = ["PointFile", "PointFileError", "write_points", "EXTENSIONS"]

#: The extensions of the files read (any letter case); a LAZ file is
#: refused with the commands that decompress it.
EXTENSIONS = (".ply", ".npy", ".xyz", ".pwn", ".off", ".las")
LAS_EXTENSIONS = (".las", ".laz")

_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


class PointFileError(ValueError):
    """A point file that cannot be read: missing, malformed or of an unknown format."""


@dataclass(frozen=True)
class _TextLayout:
    """Where the rows of a text file are: after ``skip`` lines, ``count`` of
    them (None: to the end), the points in columns ``xyz`` of ``columns``;
    the columns of ``single`` are single-precision numbers, rounded to them
    when read, as CGAL's PLY reader does."""

    skip: int = 0
    count: Optional[int] = None
    columns: Tuple[str, ...] = ("x", "y", "z")
    xyz: Tuple[int, int, int] = (0, 1, 2)
    single: Tuple[int, ...] = ()


class PointFile:
    """The points of one file, read by row ranges.

    Parameters
    ----------
    path : path-like
        A PLY file, binary or ASCII, with a ``vertex`` element of scalar
        properties ``x``, ``y``, ``z`` (other properties are ignored), a
        ``.npy`` array of shape (N, 3) or more columns (the first three are
        the points), a text ``.xyz`` / ``.pwn`` file (three or more numbers
        a line), an OFF file (its vertices) or an uncompressed LAS file,
        1.0 to 1.4, point formats 0 to 10 (its points, X * scale + offset).

    Raises
    ------
    PointFileError
        If the file is missing, or not a readable file of these formats; the
        message names the file.
    """

    def __init__(self, path: "os.PathLike[str] | str") -> None:
        self.path = Path(path)
        suffix = self.path.suffix.lower()
        if not self.path.is_file():
            raise PointFileError(f"{self.path}: no such file")
        self._rows: Optional[np.ndarray] = None  # memory-mapped: binary PLY and .npy
        self._text: Optional[_TextLayout] = None
        self.las: Optional[LASFile] = None
        self._count: Optional[int] = None  # of a text file, counted when asked for
        try:
            if suffix == ".ply":
                self._rows, self._text = _open_ply(self.path)
            elif suffix == ".npy":
                self._rows = _map_npy(self.path)
            elif suffix in (".xyz", ".pwn"):
                self._text = _TextLayout()
            elif suffix == ".off":
                self._text = _off_layout(self.path)
            elif suffix in LAS_EXTENSIONS:
                self.las = LASFile(str(self.path))
            else:
                raise PointFileError(f"unknown format: use one of {', '.join(EXTENSIONS)}")
        except PointFileError as error:
            raise PointFileError(f"{self.path}: {error}") from None
        except LASError as error:  # its message names the file
            raise PointFileError(str(error)) from None
        except (OSError, ValueError) as error:
            raise PointFileError(f"{self.path}: cannot be read: {error}") from None
        if self._rows is not None:
            self._count = len(self._rows)
        elif self.las is not None:
            self._count = len(self.las)
        elif self._text.count is not None:
            self._count = self._text.count  # announced by the header; a shorter file fails when read

    def __len__(self) -> int:
        if self._count is None:
            self._count = sum(len(block) for _, block in self._text_chunks(1 << 20, self._text.xyz))
        return self._count

    @property
    def names(self) -> Tuple[str, ...]:
        """The names of the columns of :meth:`table`: a PLY file's vertex
        properties, in the file's order; ``x``, ``y``, ``z``, then ``c3``,
        ``c4``... for a ``.npy`` array; ``x``, ``y``, ``z`` for the other files
        (:meth:`field` reads a LAS file's extra bytes)."""
        if self.las is not None:
            return ("x", "y", "z")
        if self._text is not None:
            return self._text.columns
        if self._rows.dtype.names:
            return self._rows.dtype.names
        return ("x", "y", "z") + tuple(f"c{i}" for i in range(3, self._rows.shape[1]))

    def table(self, start: int = 0, stop: Optional[int] = None) -> npt.NDArray[np.float64]:
        """Rows ``start`` to ``stop`` (default: the end) of every column of
        :attr:`names`, as a float64 array (n, len(names))."""
        if self.las is not None:
            return self.read(start, stop)
        if self._text is not None:
            return self._text_rows(start, stop, tuple(range(len(self._text.columns))))
        rows = self._rows[start:stop]
        if rows.dtype.names:
            return np.stack([rows[name] for name in rows.dtype.names], axis=1).astype(np.float64, copy=False)
        return np.array(rows, dtype=np.float64)

    def read(self, start: int = 0, stop: Optional[int] = None) -> npt.NDArray[np.float64]:
        """The points of rows ``start`` to ``stop`` (default: the end), as a float64 array (n, 3)."""
        if self.las is not None:
            return self.las.read_points(start, stop)
        if self._text is not None:
            return self._text_rows(start, stop, self._text.xyz)
        rows = self._rows[start:stop]
        if rows.dtype.names:
            out = np.empty((len(rows), 3))
            for column, name in enumerate("xyz"):
                out[:, column] = rows[name]
            return out
        return np.array(rows[:, :3], dtype=np.float64)

    def field(self, name: str, start: int = 0, stop: Optional[int] = None) -> npt.NDArray[np.float64]:
        """The extra-bytes field ``name`` of a LAS file's records ``start`` to
        ``stop``, scaled and offset as its descriptor says, as a float64 array (n,).

        Raises
        ------
        PointFileError
            If the file is not a LAS file, or has no such field of one number.
        """
        if self.las is None:
            raise PointFileError(f"{self.path}: not a LAS file: only a LAS file has extra-bytes fields")
        try:
            return self.las.read_field(name, start, stop)
        except LASError as error:
            raise PointFileError(str(error)) from None

    def chunks(self, rows: int = 1 << 20) -> Iterator[Tuple[int, npt.NDArray[np.float64]]]:
        """The points by chunks of ``rows`` rows, each with the row it starts at."""
        if self._text is not None:
            yield from self._text_chunks(rows, self._text.xyz)
            return
        for start in range(0, len(self), rows):
            yield start, self.read(start, start + rows)

    def _text_chunks(self, rows: int, columns: Tuple[int, ...]) -> Iterator[Tuple[int, npt.NDArray[np.float64]]]:
        """The ``columns`` of a text file's rows, by chunks of ``rows`` rows."""
        layout, start = self._text, 0
        with open(self.path, errors="replace") as stream:
            for _ in range(layout.skip):
                stream.readline()
            while layout.count is None or start < layout.count:
                wanted = rows if layout.count is None else min(rows, layout.count - start)
                try:
                    with warnings.catch_warnings():
                        # The end of the file, not an error: an empty block ends the loop.
                        warnings.filterwarnings("ignore", message="loadtxt: input contained no data")
                        block = np.loadtxt(stream, ndmin=2, max_rows=wanted, usecols=columns, comments="#")
                except ValueError as error:
                    raise PointFileError(
                        f"{self.path}: malformed, in the {wanted} rows from row {start}: {error}") from None
                for i, column in enumerate(columns):
                    if column in layout.single:
                        block[:, i] = block[:, i].astype(np.float32)
                if len(block) == 0:
                    if layout.count is not None:
                        raise PointFileError(
                            f"{self.path}: truncated: {layout.count} vertices announced, {start} stored")
                    return
                yield start, block
                start += len(block)

    def _text_rows(self, start: int, stop: Optional[int], columns: Tuple[int, ...]) -> npt.NDArray[np.float64]:
        stop = len(self) if stop is None else min(stop, len(self))
        parts = [block[max(start - first, 0) : stop - first] for first, block in self._text_chunks(1 << 20, columns)
                 if first < stop and first + len(block) > start]
        return np.concatenate(parts) if parts else np.empty((0, len(columns)))


def write_points(path: "os.PathLike[str] | str", columns: List[Tuple[str, npt.NDArray]]) -> None:
    """Writes ``columns`` (name, array (N,) or (N, m) of float64) to ``path``.

    A ``.ply`` file gets one double property per column (the names given, or
    the name with 0, 1, ... for a multi-column array: pass ``("x", ...)``
    etc. for the points); a ``.npy`` file one float64 array of all the
    columns side by side. Written to a temporary file in the same folder,
    renamed over ``path`` at the end.
    """
    path = Path(path)
    arrays = [np.asarray(array, dtype=np.float64).reshape(len(array), -1) for _, array in columns]
    table = np.concatenate(arrays, axis=1) if arrays else np.empty((0, 0))
    temporary = path.with_name(f".{path.name}.partial.{os.getpid()}{path.suffix}")
    try:
        with open(temporary, "wb") as stream:
            if path.suffix.lower() == ".ply":
                names = []
                for (name, _), array in zip(columns, arrays):
                    names += [name] if array.shape[1] == 1 else [f"{name}{i}" for i in range(array.shape[1])]
                stream.write(ply_header(len(table), names))
                stream.write(np.ascontiguousarray(table, dtype="<f8").tobytes())
            elif path.suffix.lower() == ".npy":
                np.save(stream, np.ascontiguousarray(table))
            else:
                raise PointFileError(f"{path}: cannot write this format: use .ply or .npy")
        os.replace(temporary, path)
    finally:
        if temporary.exists():
            temporary.unlink()


def ply_header(count: int, names: List[str]) -> bytes:
    """The header of a binary little-endian PLY file of ``count`` vertices with these double properties."""
    lines = ["ply", "format binary_little_endian 1.0", "comment cgal_rrht", f"element vertex {count}"]
    lines += [f"property double {name}" for name in names]
    lines.append("end_header")
    return ("\n".join(lines) + "\n").encode("ascii")


def _open_ply(path: Path) -> Tuple[Optional[np.ndarray], Optional[_TextLayout]]:
    """The vertices of a PLY file: memory-mapped as a structured array if it
    is binary, or where they are in it if it is ASCII."""
    with open(path, "rb") as stream:
        if stream.readline().strip() != b"ply":
            raise PointFileError("not a PLY file")
        encoding, elements, lines = None, [], 1  # elements: [name, count, [(property, dtype)]]
        while True:
            line = stream.readline()
            lines += 1
            if not line:
                raise PointFileError("the PLY header has no end_header")
            words = line.decode("ascii", "replace").split()
            if not words or words[0] in ("comment", "obj_info"):
                continue
            if words[0] == "end_header":
                break
            if words[0] == "format" and len(words) >= 2:
                encoding = words[1]
            elif words[0] == "element" and len(words) == 3 and words[2].isdigit():
                elements.append([words[1], int(words[2]), []])
            elif words[0] == "property" and elements:
                if len(words) == 5 and words[1] == "list":
                    elements[-1][2].append((words[-1], None))
                elif len(words) == 3 and words[1] in _PLY_TYPES:
                    elements[-1][2].append((words[2], _PLY_TYPES[words[1]]))
                else:
                    raise PointFileError(f"unknown PLY property: {line.decode('ascii', 'replace').strip()}")
            else:
                raise PointFileError(f"unexpected PLY header line: {line.decode('ascii', 'replace').strip()}")
        offset = stream.tell()
    if encoding == "ascii":
        return None, _ascii_ply_layout(lines, elements)
    if encoding not in ("binary_little_endian", "binary_big_endian"):
        raise PointFileError(f"unknown PLY format {encoding!r}: ascii, binary_little_endian or binary_big_endian")
    order = "<" if encoding == "binary_little_endian" else ">"
    for name, count, properties in elements:
        if any(dtype is None for _, dtype in properties):
            if name == "vertex":
                raise PointFileError("the vertices have a list property")
            raise PointFileError(f"the element '{name}' before the vertices has a list property")
        dtype = np.dtype([(p, order + t) for p, t in properties])
        if name == "vertex":
            if not {"x", "y", "z"} <= set(dtype.names or ()):
                raise PointFileError("the vertices have no x, y and z")
            if offset + count * dtype.itemsize > path.stat().st_size:
                raise PointFileError(f"truncated: {count} vertices announced, fewer stored")
            if count == 0:
                return np.empty(0, dtype=dtype), None
            return np.memmap(path, dtype=dtype, mode="r", offset=offset, shape=(count,)), None
        offset += count * dtype.itemsize
    raise PointFileError("no vertex element")


def _ascii_ply_layout(header_lines: int, elements: list) -> _TextLayout:
    """The vertices of an ASCII PLY file, one line each, after the header and
    the lines of the elements before them."""
    skip = header_lines
    for name, count, properties in elements:
        if name == "vertex":
            names = tuple(p for p, _ in properties)
            if any(dtype is None for _, dtype in properties):
                raise PointFileError("the vertices have a list property")
            if not {"x", "y", "z"} <= set(names):
                raise PointFileError("the vertices have no x, y and z")
            single = tuple(i for i, (_, dtype) in enumerate(properties) if dtype == "f4")
            return _TextLayout(skip, count, names, (names.index("x"), names.index("y"), names.index("z")), single)
        skip += count
    raise PointFileError("no vertex element")


def _off_layout(path: Path) -> _TextLayout:
    """The vertices of an OFF file (with colors or normals, as [C][N]OFF),
    after its keyword and counts, one line each."""
    lines, words = 0, []
    with open(path, errors="replace") as stream:
        while len(words) < 4:  # the keyword and the numbers of vertices, faces and edges
            line = stream.readline()
            if not line:
                raise PointFileError("the OFF header ends early")
            lines += 1
            words += line.split("#")[0].split()
    keyword = words[0]
    if not (keyword.endswith("OFF") and set(keyword[:-3]) <= set("STCN")) or not words[1].isdigit():
        raise PointFileError(f"not an OFF file of 3D points: it begins with {' '.join(words[:4])!r}")
    return _TextLayout(skip=lines, count=int(words[1]))


def _map_npy(path: Path) -> np.ndarray:
    """The rows of a ``.npy`` array of shape (N, 3 or more), memory-mapped."""
    array = np.load(path, mmap_mode="r", allow_pickle=False)
    if array.ndim != 2 or array.shape[1] < 3 or array.dtype.kind not in "fiu":
        raise PointFileError(f"not an array of points: shape {array.shape}, dtype {array.dtype} (need (N, 3), numbers)")
    return array
