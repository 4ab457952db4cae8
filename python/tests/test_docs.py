# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The documentation cannot rot. Every code block of the README and of the user manual runs
as written on the bundled data: C++ is the example programs that CMake builds and ctest runs
(copied in the README, embedded with \\include in the manual), the command lines run in
order in one folder (with this build's rrht_normals and this Python), and the Python blocks
run. The reference manual covers every public header, named parameter and setting (Doxygen,
run by scripts/build_docs.sh, fails on any undocumented member of what it reads)."""

import re
import shlex
import subprocess
import sys

import pytest

from conftest import ROOT

PAGES = {name: (ROOT / name).read_text() for name in ("README.md", "doc/user_manual.md")}
BLOCKS = {name: re.findall(r"^```(\w*)\n(.*?)^```$", text, re.M | re.S) for name, text in PAGES.items()}

# The README's set-up lines, which scripts/test.sh runs itself (the same commands, on
# build/release and build/venv), rather than this test.
SET_UP = {
    "bash scripts/demo.sh": "run by scripts/test.sh after its first build",
    "bash scripts/test.sh": "the test command itself",
    "bash scripts/install_dependencies.sh --python": "run by scripts/test.sh first",
    "/usr/bin/python3 -m venv --system-site-packages .venv": "scripts/test.sh makes build/venv so",
    ".venv/bin/pip install --no-build-isolation .": "scripts/test.sh installs build/venv so",
}
SHARED = ROOT.parent / "shared"


def blocks(page, language):
    return [code for name, code in BLOCKS[page] if name == language]


def commands(code):
    return [shlex.split(line, comments=True) for line in code.splitlines() if shlex.split(line, comments=True)]


def sh_blocks():
    return [pytest.param(page, code, id=f"{page}:{i}") for page in PAGES for i, code in enumerate(blocks(page, "sh"))]


def python_blocks():
    return [pytest.param(code, id=f"{page}:{i}") for page in PAGES for i, code in enumerate(blocks(page, "python"))]


@pytest.mark.parametrize("page", PAGES)
def test_every_block_has_a_language_that_this_test_runs(page):
    assert BLOCKS[page] and {name for name, _ in BLOCKS[page]} <= {"cpp", "sh", "python"}, \
        [name for name, _ in BLOCKS[page]]


def test_the_readme_cpp_block_is_the_example_that_ctest_runs():
    (code,) = blocks("README.md", "cpp")
    example = (ROOT / "examples" / "rrht_estimate_normals_example.cpp").read_text()
    assert code == example[example.index("#include"):]


def test_the_readme_orientation_table_is_the_benchmarks():
    # benchmark/report_orientation.py writes the table under this heading, then the open shapes.
    results = (ROOT / "benchmark" / "results" / "orientation" / "orientation.md").read_text()
    section = results[results.index("## The README's table"):]
    table = section[section.index("| closed shape"):]
    table = table[:table.index("\n#")].strip("\n")
    assert table.count("\n|") > 5 and table in PAGES["README.md"]


def test_the_manual_embeds_the_examples_that_ctest_runs():
    """The manual has no C++ of its own: it embeds the example programs, which ctest builds and runs."""
    assert not blocks("doc/user_manual.md", "cpp")
    embedded = re.findall(r"^\\include (\S+)$", PAGES["doc/user_manual.md"], re.M)
    assert embedded == ["rrht_estimate_normals_example.cpp", "rrht_pipeline_example.cpp"]
    tests = (ROOT / "examples" / "CMakeLists.txt").read_text()
    for name in embedded:
        assert (ROOT / "examples" / name).is_file()
        assert re.search(rf'add_checked_run\(\S+\s+"{name[:-len(".cpp")]};', tests), name  # run and checked


@pytest.fixture
def in_a_fresh_folder(tmp_path):
    """A folder holding only the bundled data and example scripts, under examples/, where the
    pages' commands run, with the evaluation data beside it as ../shared where the checkout has it."""
    folder = tmp_path / "checkout"
    (folder / "examples").mkdir(parents=True)
    for name in ("data", "python"):
        (folder / "examples" / name).symlink_to(ROOT / "examples" / name)
    if SHARED.is_dir():
        (tmp_path / "shared").symlink_to(SHARED)
    return folder


@pytest.mark.parametrize("page, code", sh_blocks())
def test_command_lines(page, code, cli, in_a_fresh_folder):
    """The lines of a block run in order in one folder: a later line may read what an earlier one wrote."""
    lines = [words for words in commands(code) if " ".join(words) not in SET_UP]
    if not lines:
        pytest.skip("set-up lines only, which scripts/test.sh runs itself (SET_UP)")
    if any("../shared/" in word for words in lines for word in words) and not SHARED.is_dir():
        pytest.skip(f"{SHARED} not found: {code}")
    for words in lines:
        command = " ".join(words)
        if words[0] == "build/release/examples/rrht_normals":
            words[0] = cli
        elif words[0] in (".venv/bin/python", "python"):
            words[0] = sys.executable
        else:
            pytest.fail(f"a command of {page} that this test neither runs nor lists in SET_UP: {command}")
        before = set(in_a_fresh_folder.iterdir())
        done = subprocess.run(words, cwd=in_a_fresh_folder, capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, (command, done.stderr)
        assert not re.search(r"warning|error|traceback", done.stderr, re.I), (command, done.stderr)
        assert set(in_a_fresh_folder.iterdir()) - before, f"{command} wrote no file"


@pytest.mark.parametrize("code", python_blocks())
def test_python_block(code, in_a_fresh_folder):
    done = subprocess.run([sys.executable, "-c", code], cwd=in_a_fresh_folder, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, (code, done.stderr)


def test_the_reference_reads_every_public_header():
    doxyfile = (ROOT / "doc" / "Doxyfile").read_text()
    inputs = set(re.findall(r"\.\./(include/\S+\.h)", doxyfile))
    public = {str(path.relative_to(ROOT)) for path in (ROOT / "include").rglob("*.h") if "internal" not in path.parts}
    assert inputs == public


def test_the_reference_documents_every_named_parameter():
    """Each RRHT named parameter, deprecated ones included, has its entry on the page of the function that reads it."""
    listed = re.findall(r"^\s*X\((\w+)_t, (\w+)\)", (ROOT / "include/CGAL/RRHT/parameters.h").read_text(), re.M)
    assert len(listed) > 15 and all(tag == name for tag, name in listed)
    documented = set()
    for header in ("rrht_estimate_normals.h", "rrht_orient_normals.h"):
        documented |= set(re.findall(r"\\cgalParamNBegin\{(\w+)\}", (ROOT / "include/CGAL" / header).read_text()))
    assert {name for _, name in listed} <= documented


def test_every_setting_has_one_name_in_every_tool(cli):
    """The settings of C++ are those of rrht_normals --setting, cgal_rrht.SETTINGS, and the manual's table."""
    import cgal_rrht

    names = re.findall(r'\{ "(\w+)", Setting::(\w+) \}', (ROOT / "include/CGAL/RRHT/Setting.h").read_text())
    assert [name.upper() for name, _ in names] == [value for _, value in names]
    assert cgal_rrht.SETTINGS == tuple(name for name, _ in names)
    assert all(f"Setting::{value}" in PAGES["doc/user_manual.md"] or value == "DEFAULT" for _, value in names)
    help_text = subprocess.run([cli, "--help"], capture_output=True, text=True, check=True).stdout
    assert "default, paper_precise or paper_fast" in help_text
