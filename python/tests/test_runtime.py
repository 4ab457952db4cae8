# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The call as a Python user lives with it: no copy of the input, the GIL
released, Ctrl-C honoured."""

import os
import signal
import subprocess
import sys
import threading
import time
import tracemalloc

import pytest

import cgal_rrht
from conftest import noisy_cube


def test_no_copy_of_a_contiguous_float64_array():
    """NumPy traces its allocations: a C-contiguous float64 input adds only the output."""
    points, _ = noisy_cube(200000)
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        start = tracemalloc.get_traced_memory()[0]
        cgal_rrht.estimate_normals(points, k=10, planes=5, rotations=1)
        peak = tracemalloc.get_traced_memory()[1] - start
    finally:
        tracemalloc.stop()
    assert points.nbytes <= peak < 1.25 * points.nbytes  # the output is as large as the input


def test_other_python_threads_run_meanwhile():
    """While the estimation runs in one thread, the main thread keeps running Python."""
    points, _ = noisy_cube(100000)
    done = threading.Event()
    worker = threading.Thread(target=lambda: (cgal_rrht.estimate_normals(points, threads=1), done.set()))
    iterations, longest_gap = 0, 0.0
    start = last = time.perf_counter()
    worker.start()
    while not done.is_set():
        now = time.perf_counter()
        longest_gap = max(longest_gap, now - last)
        last = now
        iterations += 1
    worker.join()
    duration = time.perf_counter() - start
    assert duration > 0.5, "the estimation was too short to tell"
    # With the GIL held, the loop would stop for the whole estimation.
    assert longest_gap < 0.25 * duration, (longest_gap, duration)
    assert iterations > 1000


INTERRUPTED = """
import signal, sys, time
# Python leaves SIGINT ignored when it starts so (a job started in the
# background by a shell): the handler of a terminal's Ctrl-C, set anyway.
signal.signal(signal.SIGINT, signal.default_int_handler)
import numpy as np
import pytest
import cgal_rrht
points = np.random.default_rng(0).random((2000000, 3))
print("started", flush=True)
start = time.perf_counter()
try:
    cgal_rrht.estimate_normals(points, k=200, confidence_interval=False, planes=5000)
except KeyboardInterrupt:
    print(f"interrupted after {time.perf_counter() - start:.2f} s", flush=True)
    sys.exit(3)
print("finished", flush=True)
"""


def test_ctrl_c_stops_a_long_run():
    """A real SIGINT, as Ctrl-C sends, raises KeyboardInterrupt within about a second."""
    process = subprocess.Popen([sys.executable, "-c", INTERRUPTED], stdout=subprocess.PIPE, text=True,
                               env=dict(os.environ))
    try:
        assert process.stdout.readline().strip() == "started"
        time.sleep(1.0)
        sent = time.perf_counter()
        process.send_signal(signal.SIGINT)
        output, _ = process.communicate(timeout=30)
        stopped_after = time.perf_counter() - sent
    finally:
        process.kill()
    assert process.returncode == 3, output
    assert output.startswith("interrupted after"), output
    assert stopped_after < 1.5, stopped_after


def test_threads_limits_the_call():
    """threads=1 keeps the call on one core: its CPU time is about its wall time."""
    if (os.cpu_count() or 1) < 2:
        pytest.skip("one core: one thread and all threads cannot be told apart")
    points, _ = noisy_cube(60000)
    wall, cpu = time.perf_counter(), time.process_time()
    cgal_rrht.estimate_normals(points, threads=1)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    assert wall > 0.3, "the estimation was too short to tell"
    assert cpu < 1.25 * wall, (cpu, wall)
