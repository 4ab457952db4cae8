# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""One tile's task, run on a Dask worker: the tile and its halo, the points of the
other tiles within a margin of its xy bounding box, estimated with their global ids;
the halo checked against the supports of its normals and widened where they reach
beyond it; its own points' normals written."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Dict, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

from . import estimate_normals, orient_normals
from .point_files import LAS_EXTENSIONS, PointFile, PointFileError, write_points

_IDS_SUFFIX = ".ids.npy"
# A LAZ file is a tile too, refused with the commands that decompress it.
_TILE_FORMATS = (".ply", ".npy") + LAS_EXTENSIONS
_CHUNK_ROWS = 1 << 20

class TileError(ValueError):
    """A tile that cannot be used (missing, malformed, empty); the message names it."""


@dataclass(frozen=True)
class Tile:
    """One tile: its file, its points' ids and the xy bounding box of its finite points."""

    path: str
    count: int
    first_id: int  # the id of its first row, when it has no ids file
    ids_path: Optional[str]
    lower: Tuple[float, float]  # (inf, inf) when no point is finite
    upper: Tuple[float, float]

    def ids(self, start: int = 0, stop: Optional[int] = None) -> npt.NDArray[np.uint64]:
        """The global ids of rows ``start`` to ``stop``."""
        stop = self.count if stop is None else stop
        if self.ids_path is None:
            return np.arange(self.first_id + start, self.first_id + stop, dtype=np.uint64)
        return np.asarray(np.load(self.ids_path, mmap_mode="r")[start:stop], dtype=np.uint64)

    def meets(self, lower: npt.ArrayLike, upper: npt.ArrayLike) -> bool:
        """Whether its bounding box meets the xy box [lower, upper]."""
        return bool(np.all(np.asarray(self.lower) <= upper) and np.all(np.asarray(self.upper) >= lower))


def scan_tile(path: str, fields: Sequence[str] = ()) -> Tuple[int, Tuple[float, float], Tuple[float, float],
                                                                Optional[str]]:
    """Checks a tile (and that it has the extra-bytes ``fields``) and returns its number of points, its xy bounding box
    and its ids file, or a TileError."""
    if Path(path).suffix.lower() not in _TILE_FORMATS:
        raise TileError(f"bad tile {path}: tiles are PLY, .npy or LAS files")
    try:
        points = PointFile(path)
        for name in fields:
            points.field(name, 0, 0)
        lower, upper, count = _xy_bounds(points)
    except PointFileError as error:
        raise TileError(f"bad tile {error}") from None
    if count == 0:
        raise TileError(f"bad tile {path}: it holds no point")
    ids_path = _ids_path(Path(path))
    if ids_path is not None:
        try:
            ids = np.load(ids_path, mmap_mode="r", allow_pickle=False)
        except (OSError, ValueError) as error:
            raise TileError(f"bad tile {path}: its ids file {ids_path} cannot be read: {error}") from None
        if ids.shape != (count,) or ids.dtype.kind not in "ui" or (ids.dtype.kind == "i" and ids.min() < 0):
            raise TileError(f"bad tile {path}: its ids file {ids_path} is not {count} non-negative integers")
    return count, tuple(lower), tuple(upper), None if ids_path is None else str(ids_path)


def _xy_bounds(points: PointFile) -> Tuple[np.ndarray, np.ndarray, int]:
    """The xy bounding box of the points whose coordinates are all finite
    ((inf, inf) and (-inf, -inf) if none is), and the number of points, in
    one pass over the file by chunks."""
    lower, upper, count = np.full(2, np.inf), np.full(2, -np.inf), 0
    for _, chunk in points.chunks(_CHUNK_ROWS):
        finite = chunk[np.isfinite(chunk).all(axis=1), :2]
        count += len(chunk)
        if len(finite):
            lower, upper = np.minimum(lower, finite.min(axis=0)), np.maximum(upper, finite.max(axis=0))
    return lower, upper, count


def estimate_tile(index: int, tiles: Sequence[Tile], halo: float, output: str, options: Dict[str, Any]) -> Dict[str, int]:
    """Estimates the normals of tile ``index`` of ``tiles`` and writes them to ``output``.

    The tile is loaded with the points of the other tiles within ``halo`` of its
    xy bounding box. Its points whose support reaches beyond that region are
    estimated again, with the points within a wider margin of them, until
    every support lies inside what was loaded. Returns counts of points.
    """
    tile = tiles[index]
    options = dict(options)
    # Each point's scanner position, in extra bytes of the tile: oriented at the end, point by point.
    fields = options.pop("viewpoint_fields", None)
    source = PointFile(tile.path)
    own = source.read()
    own_ids = tile.ids()
    extent = _extent(tiles)
    confidence = options.get("return_confidence", False)

    lower, upper = np.asarray(tile.lower) - halo, np.asarray(tile.upper) + halo
    points, ids = _load_box(tiles, lower, upper, skip=index)
    normals, confidences, support = _estimate(own, own_ids, points, ids, options)
    halo_points, estimated = len(points), len(own)
    # The distance from each point to the border of the loaded region, in xy.
    # Points with a non-finite coordinate depend on nothing.
    margin = np.minimum(own[:, :2] - lower, upper - own[:, :2]).min(axis=1)
    done = _inside(support, margin) | ~np.isfinite(own).all(axis=1) | _covers(lower, upper, extent)
    pending = np.flatnonzero(~done)
    rounds = 0
    while len(pending):
        # Again, with every point within a margin wider than the largest
        # support left, in xy, of the pending points: the cells of a quarter
        # of it within 4 cells of theirs. That is enough for a finite
        # support (the supports found on the part loaded can only shrink to
        # the true ones); an infinite one (a neighborhood that found too few
        # points), or a round after the first, doubles the margin.
        finite = support[pending][np.isfinite(support[pending])]
        halo = max(1.25 * float(finite.max()) if len(finite) else 2 * halo, 2 * halo if rounds else 0.0)
        rounds += 1
        size = halo / 4
        cells = np.unique(np.floor(own[pending, :2] / size).astype(np.int64), axis=0)
        near = _dilate(cells, 4)
        box_lower, box_upper = own[pending, :2].min(axis=0) - halo, own[pending, :2].max(axis=0) + halo
        points, ids = _load_box(tiles, box_lower, box_upper, keep=lambda xy: _in_cells(xy, size, near),
                                skip_ids=own_ids[pending])
        again = _estimate(own[pending], own_ids[pending], points, ids, options)
        halo_points, estimated = halo_points + len(points), estimated + len(pending)
        normals[pending], support[pending] = again[0], again[2]
        if confidence:
            confidences[pending] = again[1]
        whole = _covers(box_lower, box_upper, extent)
        pending = pending[~(_inside(again[2], np.full(len(pending), halo)) | whole)]

    if fields:
        normals = orient_normals(own, normals, viewpoint=scanner_positions(source, fields),
                                 threads=options.get("threads"))
    if source.las is not None:
        # Every record kept byte for byte, with the normal as extra bytes, as rrht_normals writes it.
        source.las.write_with_normals(output, normals, confidences)
    else:
        columns = [("x", own[:, 0]), ("y", own[:, 1]), ("z", own[:, 2]),
                   ("nx", normals[:, 0]), ("ny", normals[:, 1]), ("nz", normals[:, 2])]
        if confidence:
            columns.append(("confidence", confidences))
        write_points(output, columns)
    return {"points": len(own), "halo": halo_points, "estimated": estimated, "rounds": rounds}


def scanner_positions(source: PointFile, fields: Sequence[str], start: int = 0,
                      stop: Optional[int] = None) -> npt.NDArray[np.float64]:
    """The scanner position of the points of rows ``start`` to ``stop`` of a LAS file, from its extra-bytes
    ``fields`` (three names: x, y, z), as an array (n, 3)."""
    return np.stack([source.field(name, start, stop) for name in fields], axis=1)


def _estimate(points: np.ndarray, ids: np.ndarray, halo: np.ndarray, halo_ids: np.ndarray,
              options: Dict[str, Any]):
    """Normals, confidences (or None) and supports of ``points``, with ``halo`` as neighbors only."""
    normals, *rest = estimate_normals(points, ids=ids, halo=halo, halo_ids=halo_ids,
                                      return_support=True, **options)
    return normals, rest[0] if options.get("return_confidence") else None, rest[-1]


def _inside(support: np.ndarray, margin: np.ndarray) -> np.ndarray:
    # A margin for the rounding of the supports and of the distances.
    return support * (1 + 1e-9) + 1e-12 * np.abs(margin) < margin


def _covers(lower: np.ndarray, upper: np.ndarray, extent: Tuple[np.ndarray, np.ndarray]) -> bool:
    """Whether the xy box [lower, upper] holds every tile: all the cloud is then loaded."""
    return bool(np.all(lower <= extent[0]) and np.all(upper >= extent[1]))


def _extent(tiles: Sequence[Tile]) -> Tuple[np.ndarray, np.ndarray]:
    return (np.min([t.lower for t in tiles], axis=0), np.max([t.upper for t in tiles], axis=0))


def _dilate(cells: np.ndarray, reach: int) -> np.ndarray:
    """The cells within ``reach`` cells of ``cells`` in x and y, as sorted unique keys."""
    steps = range(-reach, reach + 1)
    offsets = np.array([(dx, dy) for dx in steps for dy in steps])
    return np.unique(_keys((cells[:, None, :] + offsets[None, :, :]).reshape(-1, 2)))


def _keys(cells: np.ndarray) -> np.ndarray:
    return cells[:, 0] * np.int64(1 << 31) + cells[:, 1]


def _in_cells(xy: np.ndarray, size: float, keys: np.ndarray) -> np.ndarray:
    with np.errstate(invalid="ignore"):
        cells = np.floor(xy / size)
    finite = np.isfinite(cells).all(axis=1)
    out = np.zeros(len(xy), dtype=bool)
    found = _keys(cells[finite].astype(np.int64))
    position = np.minimum(np.searchsorted(keys, found), len(keys) - 1)
    out[finite] = keys[position] == found
    return out


def _load_box(tiles: Sequence[Tile], lower: np.ndarray, upper: np.ndarray, *, skip: Optional[int] = None,
              keep=None, skip_ids: Optional[np.ndarray] = None) -> Tuple[np.ndarray, np.ndarray]:
    """The points of the tiles (but tile ``skip``, and but ``skip_ids``) in the xy box, and ``keep``, with their ids."""
    points, ids = [np.empty((0, 3))], [np.empty(0, dtype=np.uint64)]
    for t, tile in enumerate(tiles):
        if t == skip or not tile.meets(lower, upper):
            continue
        for start, chunk in PointFile(tile.path).chunks(_CHUNK_ROWS):
            xy = chunk[:, :2]
            with np.errstate(invalid="ignore"):
                inside = np.all((xy >= lower) & (xy <= upper), axis=1)
            if keep is not None:
                inside[inside] = keep(xy[inside])
            rows = np.flatnonzero(inside)
            if not len(rows):
                continue
            chunk_ids = tile.ids(start, start + len(chunk))[rows]
            if skip_ids is not None:
                fresh = ~np.isin(chunk_ids, skip_ids)
                rows, chunk_ids = rows[fresh], chunk_ids[fresh]
            points.append(chunk[rows])
            ids.append(chunk_ids)
    return np.concatenate(points), np.concatenate(ids)


def _ids_path(tile: Path) -> Optional[Path]:
    """The ids file of a tile, ``NAME.ids.npy`` next to ``NAME.EXT``, if there is one."""
    path = tile.with_name(tile.name[: -len(tile.suffix)] + _IDS_SUFFIX)
    return path if path.is_file() else None
