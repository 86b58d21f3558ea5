"""Bad command-line input is a usage error (argparse's message, exit code 2, no traceback) and an
output path that cannot be written is refused before any work, for every ``loco`` subcommand and
for ``loco-batch``."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from loco.cli import main
from loco.commands import arguments

ROOT = Path(__file__).resolve().parents[2]
BATCH = Path(os.environ.get("LOCO_BATCH_BIN", ROOT / "target" / "release" / "loco-batch"))

#: (argv, the option the error must name): every numeric option of every subcommand.
BAD_VALUES = [
    (["reproduce", "--threads", "0"], "--threads"),
    (["reproduce", "--threads", "-2"], "--threads"),
    (["reproduce", "--threads", "two"], "--threads"),
    (["reproduce", "--threads", "1.5"], "--threads"),
    (["reproduce", "--seed", "-1"], "--seed"),
    (["reproduce", "--seed", "1e3"], "--seed"),
    (["reproduce", "--seed", str(2**64)], "--seed"),
    (["reproduce", "--seed", str(2**63)], "--seed"),
    (["reproduce", "--workers", "0"], "--workers"),
    (["reproduce", "--chunk-size", "-5"], "--chunk-size"),
    (["damper-bench", "--amplitude", "0"], "--amplitude"),
    (["damper-bench", "--amplitude", "-1e-3"], "--amplitude"),
    (["damper-bench", "--amplitude", "nan"], "--amplitude"),
    (["damper-bench", "--amplitude", "inf"], "--amplitude"),
    (["frf", "--speed", "-200"], "--speed"),
    (["frf", "--speed", "fast"], "--speed"),
    (["frf", "--f-min", "0"], "--f-min"),
    (["frf", "--f-max", "nan"], "--f-max"),
    (["frf", "--n", "0"], "--n"),
    (["frf", "--n", "2.5"], "--n"),
    (["frf", "--scenario", "S_bad"], "--scenario"),
]


@pytest.mark.parametrize(("argv", "option"), BAD_VALUES, ids=lambda v: " ".join(v))
def test_a_bad_value_is_a_usage_error_naming_the_option(
    argv: list[str], option: str, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    with pytest.raises(SystemExit) as exit_:
        main([*argv, *(["--out", str(tmp_path / "out")] if argv[0] != "campaign" else [])])
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert "usage:" in err and f"argument {option}" in err, err
    # Refused before any work: nothing was written.
    assert not (tmp_path / "out").exists()


def test_frequency_bounds_in_the_wrong_order_are_a_usage_error(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    with pytest.raises(SystemExit) as exit_:
        main(["frf", "--f-min", "10", "--f-max", "5", "--out", str(tmp_path / "o")])
    assert exit_.value.code == 2
    assert "argument --f-max: must exceed --f-min" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_the_installed_command_prints_no_traceback() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "loco.cli", "reproduce", "--threads", "0"],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
    )
    assert done.returncode == 2
    assert "Traceback" not in done.stderr
    assert "loco reproduce: error: argument --threads: must be >= 1, got 0" in done.stderr


def _read_only_place(tmp_path: Path) -> Path:
    """A directory nothing can be written into, for this user."""
    if os.geteuid() == 0:
        # Permissions do not stop root: a pseudo file system where nothing can be created does.
        return Path("/proc/loco-test-output")
    place = tmp_path / "read-only"
    place.mkdir()
    place.chmod(0o555)
    return place / "out"


def _unwritable(tmp_path: Path) -> list[tuple[Path, str]]:
    a_file = tmp_path / "a_file"
    a_file.write_text("not a directory")
    return [
        (a_file, "is a file"),
        (a_file / "below", f"is under the file {a_file}"),
        (_read_only_place(tmp_path), "cannot write into"),
    ]


@pytest.mark.parametrize("command", ["reproduce", "damper-bench", "frf", "contact-report"])
def test_an_unwritable_output_is_refused_before_any_work(
    command: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    for out, reason in _unwritable(tmp_path):
        with pytest.raises(SystemExit) as exit_:
            main([command, "--out", str(out)])
        assert exit_.value.code == 2, (command, out)
        err = capsys.readouterr().err
        assert f"loco {command}: error: argument --out:" in err and reason in err, err
        assert "Traceback" not in err


def test_output_dir_creates_a_missing_directory(tmp_path: Path) -> None:
    out = arguments.output_dir(tmp_path / "a" / "b")
    assert out.is_dir() and list(out.iterdir()) == []


def test_a_parameter_loco_refuses_is_a_clean_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # A vehicle file that does not exist: loco's own error, exit 1, no traceback.
    code = main(["frf", "--out", str(tmp_path), "--vehicle", str(tmp_path / "none.toml")])
    assert code == 1
    err = capsys.readouterr().err
    assert err.startswith("loco frf: error: ") and "none.toml" in err


needs_batch = pytest.mark.skipif(not BATCH.is_file(), reason=f"{BATCH} not built")


@needs_batch
@pytest.mark.parametrize(
    ("args", "option"),
    [
        (["--threads=-1"], "--threads"),
        (["--threads", "x"], "--threads"),
        (["--threads", "100000"], "--threads"),
    ],
)
def test_batch_binary_bad_values_are_usage_errors(
    args: list[str], option: str, tmp_path: Path
) -> None:
    done = subprocess.run(
        [str(BATCH), "study.toml", "samples.csv", *args],
        capture_output=True,
        text=True,
        check=False,
        cwd=tmp_path,
        timeout=60,
    )
    assert done.returncode == 2, done.stderr
    assert option in done.stderr and done.stderr.startswith("error: invalid value")
    assert "panicked" not in done.stderr


def read_only_output(tmp_path: Path) -> tuple[Path, str]:
    """A metrics file in a place nothing can be written into, and the reason expected."""
    place = _read_only_place(tmp_path)
    if os.geteuid() == 0:
        return place / "metrics.csv", "does not exist"
    return place.parent / "metrics.csv", "cannot write"


@needs_batch
def test_batch_binary_checks_its_output_before_reading_anything(tmp_path: Path) -> None:
    # Neither the study nor the samples exist: the output is checked first, so the error is
    # about it, at once, not after a batch.
    a_file = tmp_path / "a_file"
    a_file.write_text("x")
    for output, reason in [
        (tmp_path / "missing" / "metrics.csv", "does not exist"),
        (a_file / "metrics.csv", "is not a directory"),
        (tmp_path, "is a directory"),
        read_only_output(tmp_path),
    ]:
        done = subprocess.run(
            [str(BATCH), "no-study.toml", "no-samples.csv", "-o", str(output), "--quiet"],
            capture_output=True,
            text=True,
            check=False,
            timeout=60,
        )
        assert done.returncode == 1, output
        assert "--output" in done.stderr and reason in done.stderr, done.stderr
        assert "no-study.toml" not in done.stderr
    assert not list(tmp_path.glob(".loco-batch-probe-*"))
