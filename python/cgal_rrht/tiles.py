# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Normals of clouds larger than memory: tiles with halos, on Dask.

The cloud is a set of tiles: the files of a folder (PLY, ``.npy`` or LAS:
a survey as it is delivered), or one large file cut into square tiles of the
xy plane (``split()``, or the command ``python -m cgal_rrht.tiles split``). One Dask task per tile loads the
tile and a halo, the points of the other tiles within a margin of its xy
bounding box (corners included), estimates the normals of them all with the
points' global ids (``estimate_normals(..., ids=...)``), keeps those of its own
points and writes them. The halo is checked, not assumed: where a point's
support (the ball that holds every point its normal depends on) reaches beyond
the loaded region, the point is estimated again with a halo wide enough. So
every normal is, bit for bit, the one the whole cloud in memory gives, for any
tiling and any number of workers. The normals can be oriented on the way,
towards a direction or a viewpoint, which looks at one point at a time: the
same, bit for bit, as ``orient_normals()`` on the whole cloud; in a LAS
survey, each point can be oriented towards its own scanner position, read
from extra bytes. A consistent orientation needs the whole cloud and is refused.

A LAS tile gives a LAS file: its records kept byte for byte, with the
normals as extra bytes ``NormalX``, ``NormalY``, ``NormalZ`` (and
``NormalConfidence``), written by the same code as ``rrht_normals``.

The global id of a point is its row in the tiles taken in the order of their
names, unless the tile ``NAME.EXT`` has a file ``NAME.ids.npy`` next to it
(``split()`` writes them: the rows of the points in the file it cut).

Command line::

    python -m cgal_rrht.tiles INPUT OUTPUT [--scheduler ADDRESS] [--tile-size S] [--orient=up] [options]
    python -m cgal_rrht.tiles split INPUT FOLDER --tile-size S

See ``python -m cgal_rrht.tiles --help``.
"""

from __future__ import annotations

import argparse
import logging
import math
import os
import shutil
import sys
import tempfile
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import AGGREGATIONS, SAMPLINGS, SETTINGS, _estimation_orientation, _from_setting, orient_normals
from ._tile_task import _CHUNK_ROWS, _IDS_SUFFIX, _TILE_FORMATS, Tile, TileError, _ids_path, _xy_bounds, estimate_tile, \
    scan_tile, scanner_positions
from .point_files import LAS_EXTENSIONS, PointFile, PointFileError, ply_header

__all__ = ["run", "split", "list_tiles", "TileError", "PointFileError", "Tile"]

_NO_CONSISTENT = (
    "a consistent orientation cannot be made tile by tile: each tile sees only its part of the surface, so the "
    "sign of each tile, and of each of its pieces, would be chosen on its own and neighboring tiles could disagree "
    "(and a survey's open surface has no outside to point to). Orient towards a direction instead ('up' for aerial "
    "LiDAR), a viewpoint, or each point's scanner position (viewpoint=('ScannerX', 'ScannerY', 'ScannerZ'): the "
    "names of extra-bytes fields of LAS tiles); a cloud that fits in memory can be oriented consistently with "
    "cgal_rrht.orient_normals(points, normals)")


# --------------------------------------------------------------------------
# The driver (run on the client); each tile's task is in _tile_task.py.


def list_tiles(folder: "os.PathLike[str] | str") -> List[Path]:
    """The tile files of a folder (PLY, ``.npy`` and LAS, not the ids files), by name."""
    folder = Path(folder)
    if not folder.is_dir():
        raise TileError(f"{folder}: no such folder")
    files = sorted(p for p in folder.iterdir()
                   if p.suffix.lower() in _TILE_FORMATS and not p.name.lower().endswith(_IDS_SUFFIX))
    if not files:
        raise TileError(f"{folder}: no tile (.ply, .npy or .las file) in it")
    return files


def run(input: "os.PathLike[str] | str", output: "os.PathLike[str] | str", *, scheduler: Optional[str] = None,
        workers: Optional[int] = None, threads: int = 1, tile_size: Optional[float] = None,
        halo: Optional[float] = None, progress: bool = True, return_confidence: bool = False,
        orient: Optional[Any] = None, viewpoint: Optional[Sequence[Any]] = None,
        **estimator: Any) -> Dict[str, int]:
    """Estimates the normals of a tiled cloud on Dask, tile by tile, and orients them if asked.

    Parameters
    ----------
    input : path-like
        A folder of tiles (PLY, ``.npy`` or uncompressed LAS files: binary
        PLY and ``.npy`` are memory-mapped, LAS is read by record ranges,
        ASCII PLY is parsed again wherever a halo needs it), or one point
        file (PLY, ``.npy``, ``.xyz``, ``.pwn``, ``.off``, LAS), cut first
        into tiles of ``tile_size`` in a temporary folder next to ``output``.
    output : path-like
        For a folder of tiles, a folder that receives one file per tile, of
        the same name and format: for a PLY or ``.npy`` tile, the points and
        their normals (``x y z nx ny nz`` and ``confidence`` if asked for),
        row by row as in the tile; for a LAS tile, its records byte for
        byte with the normals as extra bytes, as ``rrht_normals`` writes
        them. For one input file, one ``.ply`` or ``.npy`` file of all the
        points in the order of the input, or a ``.las`` file for a LAS
        input. Each file is written whole or not at all.
    scheduler : str, optional
        The address of a Dask scheduler (``tcp://host:8786``), whose workers
        import ``cgal_rrht`` and see the files at the same paths; default: a
        ``LocalCluster`` on this machine.
    workers : int, optional
        The number of worker processes of the ``LocalCluster``; default: one
        per core.
    threads : int, default 1
        The threads of each task's estimation (with one task per worker
        thread, as Dask runs them).
    tile_size : float, optional
        The side of the square tiles of the xy plane that one input file is
        cut into; default: about a million points a tile.
    halo : float, optional
        The first margin loaded around each tile; default: three times the
        neighborhood radius that the density of the tiles suggests (five
        with the default setting or ``refit``). Too small costs time, never accuracy: the points it
        fails are estimated again. The halo's points are only neighbors:
        they cost their reading and their place in the kd-tree.
    progress : bool, default True
        Show Dask's progress bar.
    return_confidence : bool, default False
        Also write each normal's confidence.
    orient : "up" or sequence of 3 numbers, optional
        Orient the normals towards this direction (``"up"``: (0, 0, 1), for
        aerial LiDAR), as ``estimate_normals(orient=...)``; default: not
        oriented. ``"consistent"`` is refused, before anything runs: a tile
        sees only its part of the cloud, and the sign of each tile would be
        chosen on its own (see the user manual, "Surveys and LAS").
    viewpoint : sequence of 3 numbers, or of 3 names, optional
        Orient the normals towards this point (a scanner's position), as
        ``estimate_normals(viewpoint=...)``, or, given the names of three
        extra-bytes fields of LAS tiles (``("ScannerX", "ScannerY",
        "ScannerZ")``), each normal towards its point's own scanner
        position, read from them as ``rrht_normals
        --orient=viewpoint:NAME,NAME,NAME`` reads them; not with ``orient``.
    **estimator
        The parameters of ``cgal_rrht.estimate_normals()`` (``k``,
        ``setting``, ``radius``, ``planes``, ``refit``, ``seed``...).

    Returns
    -------
    dict
        ``tiles``; ``points``; ``halo``, the points loaded as neighbors only
        (halos and second rounds); ``estimated``, the points estimated
        (second rounds included); ``rounds``, the second rounds.

    Raises
    ------
    TileError
        Before anything is written, for a missing, malformed or empty tile
        (a LAZ tile, with the commands that decompress it), or one without
        the fields of ``viewpoint``, naming it.
    ValueError
        Before anything runs, for ``orient="consistent"``, a ``viewpoint``
        other than one point or three names, names of fields for an input
        file that is not LAS, and what ``estimate_normals()`` refuses in
        ``orient`` and ``viewpoint``.
    """
    for name in ("ids", "halo", "halo_ids", "neighbors", "neighbor_ids", "return_support", "progress"):
        if name in estimator:
            raise TypeError(f"run() sets {name} itself: each task passes its tile's ids and halo")
    if isinstance(orient, str) and orient == "consistent":
        raise ValueError(_NO_CONSISTENT)
    fields = None
    if viewpoint is not None and not isinstance(viewpoint, str) and np.shape(viewpoint) == (3,) and \
            all(isinstance(name, str) for name in viewpoint):
        fields, viewpoint = tuple(viewpoint), None
    elif viewpoint is not None and (isinstance(viewpoint, str) or np.shape(viewpoint) != (3,)):
        given = repr(viewpoint) if isinstance(viewpoint, str) else f"of shape {np.shape(viewpoint)}"
        raise ValueError(f"viewpoint must be one point, 3 numbers, or, for each point's scanner position, the names "
                         f"of 3 extra-bytes fields of LAS tiles, not {given}")
    # The checks of estimate_normals(), made now rather than by each task.
    _estimation_orientation(orient, np.zeros(3) if fields else viewpoint, 0, threads, with_halo=True)
    input, output = Path(input), Path(output)
    if not input.exists():
        raise TileError(f"{input}: no such file or folder")
    options = dict(estimator, threads=threads, return_confidence=return_confidence, orient=orient,
                   viewpoint=viewpoint)
    if input.is_dir():
        if output.exists() and output.resolve() == input.resolve():
            raise ValueError(f"{output}: the output folder must not be the folder of the tiles")
        if tile_size is not None:
            raise ValueError("tile_size applies to one input file, not to a folder of tiles")
        return _run_tiles(list_tiles(input), output, scheduler, workers, halo, progress, options, fields)
    las_input = input.suffix.lower() in LAS_EXTENSIONS
    if output.suffix.lower() not in (".ply", ".npy", ".las"):
        raise ValueError(f"{output}: the output of one input file is a .ply, .npy or .las file")
    if output.suffix.lower() == ".las" and not las_input:
        raise ValueError(f"{output}: a .las output needs a LAS input, whose point records it keeps")
    if fields and not las_input:
        raise ValueError("viewpoint names fields of the extra bytes of a LAS input; give a point for this input")
    source = PointFile(input)  # a clear error now for a missing or unreadable file
    for name in fields or ():
        source.field(name, 0, 0)
    work = Path(tempfile.mkdtemp(prefix=f".{output.name}.", dir=output.parent if output.parent.is_dir() else None))
    try:
        split(input, work / "tiles", tile_size=tile_size, suffix=".npy" if las_input else output.suffix.lower())
        summary = _run_tiles(list_tiles(work / "tiles"), work / "normals", scheduler, workers, halo, progress, options)
        _merge(list_tiles(work / "tiles"), work / "normals", output, return_confidence, source, fields)
        return summary
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _run_tiles(paths: List[Path], output: Path, scheduler: Optional[str], workers: Optional[int],
               halo: Optional[float], progress: bool, options: Dict[str, Any],
               fields: Optional[Tuple[str, ...]] = None) -> Dict[str, int]:
    from distributed import Client, LocalCluster
    from distributed import progress as progress_bar

    if scheduler is None:
        # Quiet: what stops the run is raised, and Dask logs errors at its shutdown that are none (its cancelled
        # heartbeats). Its HTTP server runs even without a dashboard: on a free local port, not on 8787, which
        # another cluster may hold (a warning).
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address="127.0.0.1:0", silence_logs=logging.CRITICAL)
        client = Client(cluster)
    else:
        cluster, client = None, Client(scheduler)
    try:
        names = [str(p) for p in paths]
        scans = client.gather(client.map(scan_tile, names, fields=fields or (), pure=False))
        if fields:
            options = dict(options, viewpoint_fields=fields)
        tiles, first = [], 0
        for path, (count, lower, upper, ids_path) in zip(names, scans):
            tiles.append(Tile(path, count, first, ids_path, lower, upper))
            first += count
        if halo is None:
            halo = _first_halo(tiles, options)
        output.mkdir(parents=True, exist_ok=True)
        futures = [client.submit(estimate_tile, i, tiles, halo, str(output / Path(t.path).name), options, pure=False)
                   for i, t in enumerate(tiles)]
        if progress:
            progress_bar(futures)
        try:
            counts = client.gather(futures)
        finally:
            # A task stopped with its worker leaves its temporary file.
            for tile in tiles:
                for partial in output.glob(f".{Path(tile.path).name}.partial.*"):
                    partial.unlink(missing_ok=True)
        return {"tiles": len(tiles), **{key: sum(c[key] for c in counts) for key in counts[0]}}
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _first_halo(tiles: Sequence[Tile], options: Dict[str, Any]) -> float:
    """Three times the neighborhood radius that the median density of the tiles in xy gives, five with least squares
    first (the default), whose supports reach the neighborhoods of the neighbors' neighbors, or with refit."""
    if options.get("radius"):
        reach = float(options["radius"])
    else:
        densities = [t.count / max(np.prod(np.subtract(t.upper, t.lower)), 1e-300)
                     for t in tiles if np.all(np.isfinite(t.lower))]
        k = options.get("k", 100)
        reach = math.sqrt((k + 1) / (math.pi * float(np.median(densities)))) if densities else 1.0
    least_squares_first = _from_setting(options.get("least_squares_first"), options.get("setting", "default"))
    return (5 if least_squares_first or options.get("refit") else 3) * reach


# --------------------------------------------------------------------------
# Cutting one file into tiles, and merging the normals back.


def split(input: "os.PathLike[str] | str", folder: "os.PathLike[str] | str", *, tile_size: Optional[float] = None,
          suffix: str = ".ply") -> List[Path]:
    """Cuts a point file into square tiles of the xy plane, in one pass over it by chunks.

    Writes to ``folder`` one file per non-empty tile, ``tile_I_J.ply`` (or
    ``.npy``) holding the points with x in [I s, (I + 1) s) and y in
    [J s, (J + 1) s), s being ``tile_size``, and ``tile_I_J.ids.npy``, the rows
    of these points in ``input``: ``run()`` uses them as the points' ids, so
    that the tiles give the normals of the whole file. Points with a
    non-finite x or y go to the tile ``tile_nan.EXT``. Default ``tile_size``:
    about a million points a tile, from the xy bounding box (a pass more).
    """
    source, folder = PointFile(input), Path(folder)
    if tile_size is None:
        lower, upper, count = _xy_bounds(source)
        area = float(np.prod(upper - lower)) if count and np.all(np.isfinite(lower)) else 0.0
        tile_size = math.sqrt(area * 1e6 / count) if area > 0 else 1.0
    if not (tile_size > 0 and math.isfinite(tile_size)):
        raise ValueError(f"tile_size must be positive and finite, not {tile_size}")
    folder.mkdir(parents=True, exist_ok=True)
    parts: Dict[str, int] = {}
    for start, chunk in source.chunks(_CHUNK_ROWS):
        for name, rows in _by_tile(chunk[:, :2], tile_size):
            with open(folder / f".{name}.points.part", "ab") as stream:
                stream.write(np.ascontiguousarray(chunk[rows], dtype="<f8").tobytes())
            with open(folder / f".{name}.ids.part", "ab") as stream:
                stream.write((rows + start).astype("<u8").tobytes())
            parts[name] = parts.get(name, 0) + len(rows)
    written = []
    for name, count in sorted(parts.items()):
        _wrap(folder / f".{name}.points.part", folder / f"{name}{suffix}", count, 3)
        _wrap(folder / f".{name}.ids.part", folder / f"{name}{_IDS_SUFFIX}", count, 0)
        written.append(folder / f"{name}{suffix}")
    return written


def _by_tile(xy: np.ndarray, size: float):
    """The name of each tile that holds points of ``xy``, with their rows, increasing."""
    with np.errstate(invalid="ignore"):
        cells = np.floor(xy / size)
    finite = np.isfinite(cells).all(axis=1)
    if not finite.all():
        yield "tile_nan", np.flatnonzero(~finite)
    rows = np.flatnonzero(finite)
    cells, inverse = np.unique(cells[finite].astype(np.int64), axis=0, return_inverse=True)
    order = np.argsort(inverse.ravel(), kind="stable")
    bounds = np.searchsorted(inverse.ravel()[order], np.arange(len(cells) + 1))
    for c, (i, j) in enumerate(cells):
        yield f"tile_{i}_{j}", rows[order[bounds[c] : bounds[c + 1]]]


def _wrap(raw: Path, path: Path, count: int, columns: int) -> None:
    """Puts a header before the raw little-endian rows of ``raw`` (doubles, or uint64 ids if ``columns`` is 0)."""
    with open(path, "wb") as out, open(raw, "rb") as data:
        if path.suffix.lower() == ".ply":
            out.write(ply_header(count, ["x", "y", "z"]))
        else:
            shape = (count, columns) if columns else (count,)
            np.lib.format.write_array_header_1_0(
                out, {"descr": "<f8" if columns else "<u8", "fortran_order": False, "shape": shape})
        shutil.copyfileobj(data, out, 1 << 24)
    raw.unlink()


def _merge(tiles: List[Path], normals: Path, output: Path, confidence: bool, source: PointFile,
           fields: Optional[Tuple[str, ...]] = None) -> None:
    """Writes the normals of the tiles (in the folder ``normals``) into one file, each point at the row of its id,
    oriented towards each point's scanner position in the extra-bytes ``fields`` of ``source`` if they are given.
    A LAS output is ``source``'s records with the normals; the others, the points and their normals."""
    names = ["x", "y", "z", "nx", "ny", "nz"] + (["confidence"] if confidence else [])
    count = sum(len(PointFile(t)) for t in tiles)
    temporary = output.with_name(f".{output.name}.partial.{os.getpid()}{output.suffix}")
    las = output.suffix.lower() == ".las"
    try:
        confidences = None
        if las:  # the normals and the confidences, in arrays on disk, in the folder of the run
            table = np.lib.format.open_memmap(normals / "normals.npy", mode="w+", dtype="<f8", shape=(count, 3))
            if confidence:
                confidences = np.lib.format.open_memmap(normals / "confidences.npy", mode="w+", dtype="<f8",
                                                        shape=(count,))
        else:
            with open(temporary, "wb") as stream:
                if output.suffix.lower() == ".ply":
                    stream.write(ply_header(count, names))
                else:
                    np.lib.format.write_array_header_1_0(
                        stream, {"descr": "<f8", "fortran_order": False, "shape": (count, len(names))})
                offset = stream.tell()
                stream.truncate(offset + 8 * len(names) * count)
            table = np.memmap(temporary, dtype="<f8", mode="r+", offset=offset, shape=(count, len(names)))
        normal_columns = slice(0, 3) if las else slice(3, 6)
        for tile in tiles:
            ids = np.load(_ids_path(tile), mmap_mode="r")
            for start in range(0, len(ids), _CHUNK_ROWS):
                rows = _columns(normals / tile.name, start, start + _CHUNK_ROWS, len(names))
                rows_ids = np.asarray(ids[start : start + len(rows)])
                table[rows_ids] = rows[:, 3:6] if las else rows
                if confidences is not None:
                    confidences[rows_ids] = rows[:, 6]
        for start in range(0, count if fields else 0, _CHUNK_ROWS):
            block = table[start : start + _CHUNK_ROWS]
            block[:, normal_columns] = orient_normals(
                source.read(start, start + len(block)), block[:, normal_columns],
                viewpoint=scanner_positions(source, fields, start, start + len(block)))
        table.flush()
        if las:
            source.las.write_with_normals(str(output), table, confidences)
            del table, confidences
        else:
            del table
            os.replace(temporary, output)
    finally:
        if temporary.exists():
            temporary.unlink()


def _columns(path: Path, start: int, stop: int, count: int) -> np.ndarray:
    """Rows ``start`` to ``stop`` of the first ``count`` columns of a file written by ``write_points()``."""
    return PointFile(path).table(start, stop)[:, :count]


# --------------------------------------------------------------------------
# Command line.


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python -m cgal_rrht.tiles",
        description="Normals of a cloud larger than memory, tile by tile with halos, on Dask: the same normals, "
        "bit for bit, as the whole cloud in memory. INPUT: a folder of tiles (PLY, .npy or LAS, the ids "
        "being the rows of the tiles in name order, or NAME.ids.npy), or one point file "
        "(.ply, .npy, .xyz, .pwn, .off, .las) cut into tiles first. OUTPUT: a folder of tiles with normals (a LAS "
        "tile's records with the normals as extra bytes), or one .ply, .npy or .las file for one input file. "
        "'python -m cgal_rrht.tiles split INPUT FOLDER --tile-size S' only cuts a file into tiles. Exit codes: 1 "
        "for an input that cannot be read, 2 for a wrong command line.",
    )
    parser.add_argument("input", help="a folder of tiles, or one point file")
    parser.add_argument("output", help="a folder (for a folder of tiles) or a .ply, .npy or .las file")
    parser.add_argument("--scheduler", metavar="ADDRESS", help="a Dask scheduler (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, help="worker processes of the LocalCluster (default: one per core)")
    parser.add_argument("--threads", type=int, default=1, help="threads of each task's estimation (default 1)")
    parser.add_argument("--tile-size", type=float, help="side of the tiles one input file is cut into "
                        "(default: about a million points a tile)")
    parser.add_argument("--halo", type=float, help="first margin loaded around each tile (default: from the density)")
    parser.add_argument("--confidence", action="store_true", help="also write each normal's confidence")
    parser.add_argument("--orient", nargs="?", const="consistent", type=_orientation_flag,
                        metavar="up|X,Y,Z|viewpoint:X,Y,Z|viewpoint:NAME,NAME,NAME",
                        help="orient the normals: --orient=up (aerial surveys), --orient=X,Y,Z towards a direction, "
                        "--orient=viewpoint:X,Y,Z towards a scanner position, --orient=viewpoint:NAME,NAME,NAME "
                        "towards each point's scanner position, in these extra-bytes fields of LAS tiles (the values "
                        "of rrht_normals --orient; its consistent orientation, --orient alone, cannot be made tile "
                        "by tile and is refused)")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    estimator = parser.add_argument_group("the estimator (as rrht_normals and cgal_rrht.estimate_normals)")
    estimator.add_argument("-k", "--neighbors", type=int, default=100, help="K, the number of neighbors (default 100)")
    estimator.add_argument("-r", "--radius", type=float, help="r, the neighborhood ball radius")
    estimator.add_argument("--planes", type=int,
                           help="T_R, the most planes per accumulator (default: eq. 7, 300 with --setting paper_fast)")
    estimator.add_argument("--setting", choices=SETTINGS, default="default",
                           help="least squares first with the adaptive Hough transform (default), or the paper's "
                           "precise or fast setting")
    estimator.add_argument("--rotations", type=int, help="n_rot (default 5, 2 with --setting paper_fast)")
    estimator.add_argument("--slices", type=int, default=15, help="n_phi (default 15)")
    estimator.add_argument("--sampling", choices=SAMPLINGS, default="points")
    estimator.add_argument("--presampling", type=int, default=4, help="c (default 4)")
    estimator.add_argument("--aggregation", choices=AGGREGATIONS, default="cluster")
    estimator.add_argument("--cluster-angle", type=float, default=45.0, help="a_cluster in degrees (default 45)")
    estimator.add_argument("--no-confidence-interval", action="store_true", help="do not stop early (eq. 10)")
    estimator.add_argument("--refit", action="store_true", help="refit each normal by least squares")
    deprecated = parser.add_argument_group("deprecated options, replaced by --setting")
    deprecated.add_argument("--adaptive", action="store_const", const=True,
                            help="with a paper setting, its adaptive Hough transform without least squares")
    deprecated.add_argument("--least-squares-first", action="store_const", const=True,
                            help="with a paper setting, its least squares first")
    estimator.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    return parser


def _orientation_flag(text: str) -> Tuple[str, Any]:
    """The value of ``--orient`` as ("orient", value) or ("viewpoint", point or field names), in the syntax of
    ``rrht_normals``."""
    if text in ("consistent", "mst", "up"):
        # Both consistent orientations of rrht_normals are refused by run(), with the reason.
        return ("orient", "up" if text == "up" else "consistent")
    keyword, words = ("viewpoint", text[len("viewpoint:"):]) if text.startswith("viewpoint:") else ("orient", text)
    words = words.split(",")
    try:
        values: Tuple[Any, ...] = tuple(float(word) for word in words)
    except ValueError:  # the names of three fields, as a viewpoint
        values = tuple(words) if keyword == "viewpoint" and all(words) else ()
    if len(values) != 3:
        raise argparse.ArgumentTypeError(
            f"must be up, X,Y,Z, viewpoint:X,Y,Z or viewpoint:NAME,NAME,NAME, not {text!r}")
    return (keyword, values)


def main(argv: Optional[Sequence[str]] = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        if argv[:1] == ["split"]:
            parser = argparse.ArgumentParser(prog="python -m cgal_rrht.tiles split",
                                             description="Cuts a point file into square tiles of the xy plane, "
                                             "with the ids files that keep the normals those of the whole file.")
            parser.add_argument("input")
            parser.add_argument("folder")
            parser.add_argument("--tile-size", type=float, help="side of the tiles (default: about 1M points a tile)")
            parser.add_argument("--format", choices=("ply", "npy"), default="ply")
            args = parser.parse_args(argv[1:])
            written = split(args.input, args.folder, tile_size=args.tile_size, suffix="." + args.format)
            print(f"{len(written)} tiles in {args.folder}")
            return 0
        args = _parser().parse_args(argv)
        for flag, given in (("--adaptive", args.adaptive), ("--least-squares-first", args.least_squares_first)):
            if given:
                print(f"warning: {flag} is deprecated and will be removed: use --setting", file=sys.stderr)
        orientation = dict([args.orient]) if args.orient else {}
        summary = run(args.input, args.output, scheduler=args.scheduler, workers=args.workers, threads=args.threads,
                      tile_size=args.tile_size, halo=args.halo, progress=not args.quiet,
                      return_confidence=args.confidence, **orientation, k=args.neighbors, setting=args.setting,
                      radius=args.radius, planes=args.planes,
                      rotations=args.rotations, slices=args.slices, sampling=args.sampling,
                      presampling=args.presampling, aggregation=args.aggregation, cluster_angle=args.cluster_angle,
                      confidence_interval=not args.no_confidence_interval, adaptive=args.adaptive,
                      least_squares_first=args.least_squares_first, refit=args.refit, seed=args.seed)
    except (TileError, PointFileError) as error:  # an input that cannot be read, as rrht_normals says it
        print(f"error: {error}", file=sys.stderr)
        return 1
    except (ValueError, TypeError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    if not args.quiet:
        print(f"{summary['points']} points in {summary['tiles']} tiles, with {summary['halo']} halo points; "
              f"{summary['estimated'] - summary['points']} estimated again in {summary['rounds']} second rounds: "
              f"{args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
