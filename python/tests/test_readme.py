# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every code block of the README runs as written on the bundled data, so that the front
page cannot rot: its C++ block is the example that CMake builds and ctest runs, its command
lines run (with this build's rrht_normals and this Python), and its Python blocks run."""

import re
import shlex
import subprocess
import sys

import pytest

from conftest import ROOT

README = (ROOT / "README.md").read_text()
BLOCKS = re.findall(r"^```(\w*)\n(.*?)^```$", README, re.M | re.S)

# The README's set-up lines, which scripts/test.sh runs itself (the same commands, on
# build/release and build/venv), rather than this test.
SET_UP = {
    "bash scripts/demo.sh": "run by scripts/test.sh after its first build",
    "bash scripts/test.sh": "the test command itself",
    "bash scripts/install_dependencies.sh --python": "run by scripts/test.sh first",
    "/usr/bin/python3 -m venv --system-site-packages .venv": "scripts/test.sh makes build/venv so",
    ".venv/bin/pip install --no-build-isolation .": "scripts/test.sh installs build/venv so",
}


def blocks(language):
    return [code for name, code in BLOCKS if name == language]


def command_lines():
    return [line for code in blocks("sh") for line in code.splitlines() if shlex.split(line, comments=True)]


def test_every_block_has_a_language_that_this_test_runs():
    assert BLOCKS and {name for name, _ in BLOCKS} <= {"cpp", "sh", "python"}, [name for name, _ in BLOCKS]


def test_the_cpp_block_is_the_example_that_ctest_runs():
    (code,) = blocks("cpp")
    example = (ROOT / "examples" / "rrht_estimate_normals_example.cpp").read_text()
    assert code == example[example.index("#include"):]


SHARED = ROOT.parent / "shared"


@pytest.fixture
def in_a_fresh_folder(tmp_path, monkeypatch):
    """A folder holding only the bundled data, as examples/data, where the README's commands
    run, with the evaluation data beside it as ../shared where the checkout has it."""
    folder = tmp_path / "checkout"
    (folder / "examples").mkdir(parents=True)
    (folder / "examples" / "data").symlink_to(ROOT / "examples" / "data")
    if SHARED.is_dir():
        (tmp_path / "shared").symlink_to(SHARED)
    return folder


@pytest.mark.parametrize("line", command_lines())
def test_command_line(line, cli, in_a_fresh_folder):
    words = shlex.split(line, comments=True)
    command = " ".join(words)
    if command in SET_UP:
        return  # see SET_UP: scripts/test.sh runs it
    if "../shared/" in command and not SHARED.is_dir():
        pytest.skip(f"{SHARED} not found: {command}")
    if words[0] == "build/release/examples/rrht_normals":
        words[0] = cli
    elif words[0] in (".venv/bin/python", "python"):
        words[0] = sys.executable
    else:
        pytest.fail(f"a README command that this test neither runs nor lists in SET_UP: {command}")
    done = subprocess.run(words, cwd=in_a_fresh_folder, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, (command, done.stderr)
    assert not re.search(r"warning|error|traceback", done.stderr, re.I), (command, done.stderr)
    written = [path.name for path in in_a_fresh_folder.iterdir() if path.name != "examples"]
    assert written, f"{command} wrote no file"


@pytest.mark.parametrize("code", blocks("python"))
def test_python_block(code, in_a_fresh_folder):
    done = subprocess.run([sys.executable, "-c", code], cwd=in_a_fresh_folder, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, (code, done.stderr)
