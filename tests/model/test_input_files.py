"""Model files and dicts read within budgets: YAML 1.2, aliases, nesting, digits, size;
regular files only (no named pipe, device, socket or directory), for models and reports."""

from __future__ import annotations

import copy
import json
import os
import socket
import tempfile
import threading
import time

import numpy as np
import pytest
import sympy as sp
from bounded_run import run_coopkin
from typer.testing import CliRunner

from coopkin_sym import limits, load
from coopkin_sym.cli import app
from coopkin_sym.model import input_files
from coopkin_sym.model.examples import example_path
from coopkin_sym.model.input_files import read_input_bytes
from coopkin_sym.model.model import ModelError
from coopkin_sym.model.trees import TreeError, check_tree, read_text

runner = CliRunner()
BASE = {"name": "x", "parameters": ["L"],
        "arms": [{"name": "a1", "joints": [{"name": "q1", "type": "revolute",
                                            "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
        "contacts": [{"name": "c1", "link": "a1/1", "point": ["L", 0, 0],
                      "normal": [1, 0, 0], "model": "hard"}]}
YAML = """name: x
parameters: [L]
arms:
  - name: a1
    joints: [{name: q1, type: revolute, axis: [0, 0, 1], point: [0, 0, 0]}]
contacts:
  - {name: c1, link: a1/1, point: [L, POINT, 0], normal: [1, 0, 0], model: hard}
"""


def model(**changes) -> dict:
    tree = copy.deepcopy(BASE)
    tree["contacts"][0].update(changes)
    return tree


def problems(source) -> str:
    with pytest.raises(ModelError) as info:
        load(source)
    return str(info.value)


def yaml_file(tmp_path, point: str, name: str = "m.yaml"):
    path = tmp_path / name
    path.write_text(YAML.replace("POINT", point))
    return path


# ------------------------------------------------------------------ YAML 1.1 surprises


@pytest.mark.parametrize(("written", "message"), [
    ("010", "010 is ambiguous (YAML 1.1 reads a leading zero as octal: 8)"),
    ("1:30", "'1:30' is ambiguous"),
    ("0x1F", "'0x1F' is ambiguous"),
    ("0o17", "'0o17' is ambiguous"),
    ("-012", "ambiguous"),
])
def test_yaml_forms_read_differently_by_yaml_1_1_are_refused(tmp_path, written, message):
    assert message in problems(yaml_file(tmp_path, written))


def test_yaml_1_2_values(tmp_path):
    tree = read_text("a: [yes, no, on, off, true, False, ~, 1_000, 2.50, '1:30', '010']")
    assert tree == {"a": ["yes", "no", "on", "off", True, False, None, 1000, "2.50",
                          "1:30", "010"]}
    assert load(yaml_file(tmp_path, "1_000.5")).model.contacts[0].point[1] == \
        sp.Rational(2001, 2)
    # quoted, '010' is text, and the number parser refuses it the same way
    assert "leading zero" in problems(yaml_file(tmp_path, "'010'"))


def test_python_tags_are_refused():
    with pytest.raises(TreeError, match="tag .* is not accepted"):
        read_text("a: !!python/object/apply:os.system ['touch x']")
    with pytest.raises(TreeError, match="tag .* is not accepted"):
        read_text("a: !!python/name:os.system")


# ------------------------------------------------------------------ aliases and nesting


def alias_bomb(levels: int = 9) -> str:
    lines = ['a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]']
    for i in range(1, levels + 1):
        prev, cur = chr(96 + i), chr(97 + i)
        lines.append(f"{cur}: &{cur} [" + ",".join([f"*{prev}"] * 9) + "]")
    return "\n".join(lines) + "\n"


def test_alias_bomb_is_refused_at_once_without_expanding(tmp_path):
    path = tmp_path / "bomb.yaml"
    path.write_text(alias_bomb())
    assert path.stat().st_size < 1024
    start = time.monotonic()
    message = problems(path)
    assert time.monotonic() - start < 1.0
    assert "more than 1,000,000 entries once aliases are expanded" in message
    assert "lol" not in message and len(message) < 300


def test_honest_aliases_are_fine(tmp_path):
    path = tmp_path / "alias.yaml"
    path.write_text(YAML.replace("POINT", "0").replace("normal: [1, 0, 0]", "normal: *z")
                    .replace("axis: [0, 0, 1]", "axis: &z [0, 0, 1]"))
    assert load(path).model.contacts[0].normal == (0, 0, 1)


@pytest.mark.parametrize("suffix", [".yaml", ".json"])
def test_deep_nesting_is_one_line(tmp_path, suffix):
    path = tmp_path / f"deep{suffix}"
    path.write_text('{"name": ' + "[" * 100_000 + "]" * 100_000 + "}")
    message = problems(path)
    assert ("nested more than 32 deep" in message or "maximum nesting depth" in message)
    assert message.count("\n") == 0


def test_deep_dict_is_one_line():
    deep: object = 1
    for _ in range(5000):
        deep = [deep]
    message = problems({"name": "x", "parameters": deep})
    assert "nested more than 32 deep" in message


def test_dict_that_contains_itself():
    tree = model()
    tree["arms"][0]["joints"].append(tree["arms"][0])
    assert "contains itself" in problems(tree)
    shared = [0, 0, 1]
    tree = model(normal=shared)
    tree["arms"][0]["joints"][0]["axis"] = shared       # one list used twice: fine
    assert load(tree).model.contacts[0].normal == (0, 0, 1)


def test_entries_are_counted(monkeypatch):
    monkeypatch.setattr(limits, "MAX_NODES", 100)
    with pytest.raises(TreeError, match="more than 100 entries"):
        check_tree({"a": list(range(200))})


# ------------------------------------------------------------------ numbers and names


def test_integers_over_4300_digits_are_one_line_errors(tmp_path):
    big = "9" * 5000
    assert "more than 1000 digits" in problems(yaml_file(tmp_path, big))
    path = tmp_path / "m.json"
    path.write_text(json.dumps(BASE).replace('"point": ["L", 0, 0]',
                                             f'"point": ["L", {big}, 0]'))
    assert "more than 1000 digits" in problems(path)
    assert "more than 1000 digits" in problems(model(point=["L", 10**5000 - 1, 0]))
    message = problems(model(link="a1/" + big))
    assert "no link 999999999999..." in message and len(message) < 200


def test_numpy_values_in_a_model():
    m = load(model(point=[np.float64(0.5), np.int64(2), 0])).model
    assert m.contacts[0].point == (sp.Rational(1, 2), 2, 0)
    assert "numpy float32, which is not exact" in problems(
        model(point=[np.float32(0.5), 0, 0]))


def test_at_with_numpy_values():
    system = load("paper-case2-hard")
    a = system.analyze(at={"L": np.int64(2), "q4": np.float64(0.25)})
    assert a.configuration.parameters["L"] == 2
    assert a.configuration.prismatic["q4"] == sp.Rational(1, 4)
    with pytest.raises(Exception, match="numpy float32"):
        system.analyze(at={"q4": np.float32(0.25)})


def test_a_thousand_unused_parameters_are_fine():
    tree = model()
    tree["parameters"] = ["L"] + [f"P{i}" for i in range(1000)]
    assert load(tree).analyze().numbers == load(BASE).analyze().numbers


def test_large_honest_systems_still_load(tmp_path):
    arms, contacts = 200, 2000
    tree = {"name": "big", "parameters": ["L", "M"],
            "arms": [{"name": f"a{i}", "joints": [
                {"name": f"q{i}_1", "type": "revolute", "axis": [0, 0, 1], "point": [i, 0, 0]},
                {"name": f"d{i}_2", "type": "prismatic", "axis": ["3/5", "4/5", 0]}]}
                for i in range(arms)],
            "contacts": [{"name": f"c{k}", "link": f"a{k % arms}/{1 + k % 2}",
                          "point": [f"{k}/7", "L/2 + M", "0.25"], "normal": [0, 0, 1],
                          "model": ["hard", "soft", "complete", "frictionless"][k % 4]}
                         for k in range(contacts)]}
    start = time.monotonic()
    m = load(tree).model
    assert (len(m.arms), len(m.contacts)) == (arms, contacts)
    path = tmp_path / "big.json"
    path.write_text(json.dumps(tree))
    assert len(load(path).model.contacts) == contacts
    assert time.monotonic() - start < 30


# ------------------------------------------------------------------ files


def test_long_file_name():
    message = problems("x" * 100_000)
    assert "File name too long" in message and len(message) < 300


def test_dev_zero_and_directories():
    start = time.monotonic()
    assert problems("/dev/zero") == "/dev/zero: is a character device, not a regular file"
    assert time.monotonic() - start < 2
    assert problems("/") == "/: is a directory, not a file"


@pytest.fixture
def fifo(tmp_path):
    """A named pipe that nobody writes to: a reader that opens it blocks forever."""
    path = tmp_path / "pipe.yaml"
    os.mkfifo(path)
    yield path
    try:   # a reader blocked on it (a regression) gets an end of file
        os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))
    except OSError:
        pass


@pytest.fixture
def socket_file():
    """A Unix socket in a short temporary folder (their paths are short)."""
    folder = tempfile.mkdtemp(prefix="ck")
    path = os.path.join(folder, "s.yaml")
    server = socket.socket(socket.AF_UNIX)
    server.bind(path)
    yield path
    server.close()
    os.unlink(path)
    os.rmdir(folder)


def in_thread(call, seconds: float = 10.0):
    """``call()`` in a thread, its result or exception; the test fails (instead of
    hanging) when it is still running after ``seconds``."""
    out: list = []

    def run():
        try:
            out.append(call())
        except Exception as exc:  # noqa: BLE001 - handed to the test
            out.append(exc)

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"still running after {seconds} s"
    return out[0]


def test_a_named_pipe_as_model_file_is_refused_before_it_is_read(fifo):
    error = in_thread(lambda: load(fifo))
    assert isinstance(error, ModelError)
    assert error.problems == ["is a named pipe (FIFO), not a regular file"]
    assert str(error) == f"{fifo}: is a named pipe (FIFO), not a regular file"


def test_a_named_pipe_as_model_file_on_the_command_line(fifo):
    done = run_coopkin("analyze", str(fifo), timeout=30)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == f"coopkin: error: {fifo}: is a named pipe (FIFO), not a " \
                          f"regular file\n"


def test_sockets_and_devices_are_refused(socket_file):
    assert problems(socket_file) == f"{socket_file}: is a socket, not a regular file"
    assert problems("/dev/null") == "/dev/null: is a character device, not a regular file"


def test_a_file_swapped_for_a_pipe_after_the_check_is_refused(fifo, monkeypatch):
    """The kind is checked again on the opened file: a path that was a regular file
    when it was looked at and is a pipe when it is opened is still refused (opening
    it does not block)."""
    regular = os.stat(__file__)
    real_stat = os.stat

    def stat_before_the_swap(path, *args, **kwargs):
        return regular if os.fspath(path) == os.fspath(fifo) else \
            real_stat(path, *args, **kwargs)

    monkeypatch.setattr(input_files.os, "stat", stat_before_the_swap)
    error = in_thread(lambda: read_input_bytes(fifo))
    assert isinstance(error, TreeError)
    assert str(error) == "is a named pipe (FIFO), not a regular file"


def test_no_more_than_the_limit_is_read(tmp_path, monkeypatch):
    monkeypatch.setattr(limits, "MAX_FILE_BYTES", 100)
    path = tmp_path / "m.yaml"
    path.write_bytes(b"#" * 100)
    assert read_input_bytes(path) == b"#" * 100
    path.write_bytes(b"#" * 101)
    with pytest.raises(TreeError, match=r"^the file is larger than 100 bytes \(the limit "
                                        r"for a model file, a URDF file or a report\)$"):
        read_input_bytes(path)


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="needs /proc")
def test_a_file_whose_size_is_not_known_is_read_up_to_the_limit(monkeypatch):
    """Files of /proc say they are empty: what is read is still bounded."""
    assert os.stat("/proc/self/status").st_size == 0
    monkeypatch.setattr(limits, "MAX_FILE_BYTES", 100)
    with pytest.raises(TreeError, match="larger than 100 bytes"):
        read_input_bytes("/proc/self/status")


def test_missing_and_unreadable_files(tmp_path):
    with pytest.raises(TreeError, match="^no such file$"):
        read_input_bytes(tmp_path / "none.yaml")
    with pytest.raises(TreeError, match="^cannot read the file: embedded null byte$"):
        read_input_bytes("a\x00b")
    loop = tmp_path / "loop.yaml"
    loop.symlink_to(loop)
    with pytest.raises(TreeError, match="^cannot read the file: Too many levels of "
                                        "symbolic links$"):
        read_input_bytes(loop)


def test_a_report_read_back_is_checked_like_a_model_file(fifo, tmp_path, monkeypatch):
    done = run_coopkin("verify", "paper-case1-hard", str(fifo), timeout=30)
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == f"coopkin: error: {fifo}: is a named pipe (FIFO), not a " \
                          f"regular file\n"
    result = runner.invoke(app, ["verify", "paper-case1-hard", str(tmp_path)])
    assert result.exit_code == 2
    assert result.stderr == f"coopkin: error: {tmp_path}: is a directory, not a file\n"
    most = example_path("paper-case1-hard").stat().st_size   # the model is read
    report = tmp_path / "r.json"
    report.write_text("{}" + " " * (most - 1))
    monkeypatch.setattr(limits, "MAX_FILE_BYTES", most)
    result = runner.invoke(app, ["verify", "paper-case1-hard", str(report)])
    assert result.exit_code == 2
    assert result.stderr == (f"coopkin: error: {report}: the file is larger than "
                             f"{most:,} bytes (the limit for a model file, a URDF file "
                             f"or a report)\n")


def test_a_50_mb_yaml_is_refused_at_once(tmp_path):
    path = tmp_path / "huge.yaml"
    with open(path, "w") as fh:
        fh.write(YAML.replace("POINT", "0"))
        fh.write("# " + "x" * (50 * 1024 * 1024) + "\n")
    start = time.monotonic()
    assert "larger than 8.0 MB" in problems(path)
    assert time.monotonic() - start < 2


def test_nul_bytes_and_binary(tmp_path):
    path = tmp_path / "bin.yaml"
    path.write_bytes(b"name: x\x00\n")
    assert "NUL bytes" in problems(path)
    path.write_bytes(b"\xff\xfe\x00")
    assert "not a text file" in problems(path)


def test_cli_errors_from_files_are_one_line(tmp_path):
    bomb = tmp_path / "bomb.yaml"
    bomb.write_text(alias_bomb())
    for args in (["analyze", str(bomb)], ["analyze", "/dev/zero"],
                 ["analyze", "x" * 100_000], ["analyze", str(yaml_file(tmp_path, "010"))]):
        result = runner.invoke(app, args)
        assert result.exit_code == 2
        assert result.stderr.startswith("coopkin: error: ")
        assert result.stderr.count("\n") == 1
        assert "Traceback" not in result.output
