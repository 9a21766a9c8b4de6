"""RobotFix against its floor (ast.parse) and a peer (mypy), on the same files.

One command; prints a table and writes it, with machine information, to
docs/performance.md:

    python benchmarks/peers.py [--real DIR ...] [--no-download] [--out FILE]

Workloads: the thesis's 40 seed programs, with every seed's msg/ folder (one
catalog: a type several seeds define takes the first folder's definition); a
generated annotated module of 10,000 lines (benchmarks/generate_annotated.py); real
ROS Python, downloaded with pip at benchmark time into a temporary folder (the
ros-rclpy, catkin-pkg and rospkg packages; nothing is committed), plus any --real
folders (e.g. checkouts of ros2/demos). RobotFix and mypy run as fresh processes
without caches (RobotFix with -j 1, and again with all cores); ast.parse and RobotFix
are also timed in-process.
A RobotFix run that fails (exit status 2), or whose status is not the one its findings
call for, stops the benchmark; on the seed programs the in-process run's findings must
be exactly the tests' (benchmarks/seeds.py).
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import datetime
import os
import platform
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import warnings
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(Path(__file__).resolve().parent))

from generate_annotated import generate  # noqa: E402
from seeds import FOUND, folders, msg_folders, programs, verify  # noqa: E402

from robotfix import __version__  # noqa: E402
from robotfix.api import check_paths, python_files  # noqa: E402
from robotfix.config import Config  # noqa: E402

PACKAGES = ("ros-rclpy", "catkin-pkg", "rospkg")
NOTES = "<!-- notes: kept when the benchmark rewrites this file -->"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--real", action="append", type=Path, default=[])
    parser.add_argument("--no-download", action="store_true")
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "performance.md")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        work = Path(scratch)
        seeds = folders()
        workloads = [("seed programs (40)", programs(seeds), msg_folders(seeds), True)]
        generated = work / "generated" / "annotated_node.py"
        generated.parent.mkdir()
        generated.write_text(generate(10_000))
        workloads.append(("generated, annotated", [generated], [], False))
        real = list(args.real)
        if not args.no_download:
            real.append(download(work / "real"))
        real_files = python_files([r for r in real if r.exists()])
        if real_files and _has_module("mypy"):
            kept = mypy_checkable(real_files, work / "mypy-filter")
            dropped = len(real_files) - len(kept)
            print(
                f"real code: {dropped} files mypy cannot check are left out "
                "for both tools"
            )
            real_files = kept
        if real_files:
            workloads.append(("real ROS code, unannotated", real_files, [], False))
        rows = [measure(*workload, work) for workload in workloads]
    startup = statistics.median(
        timed([sys.executable, "-m", "robotfix", "--version"], statuses=(0,))
        for _ in range(10)
    )
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    report = render(rows, startup, peak, real)
    print(report)
    notes = ""
    if args.out.exists():  # keep the hand-written reading below the marker
        previous = args.out.read_text(encoding="utf-8")
        if NOTES in previous:
            notes = previous[previous.index(NOTES) :]
    args.out.write_text(report + "\n" + notes, encoding="utf-8")
    print(f"written to {args.out}")


def download(folder: Path) -> Path:
    """Real ROS Python from PyPI wheels and sdists, unpacked into `folder`."""
    folder.mkdir(parents=True)
    wheels = folder / "wheels"
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "download",
            "--no-deps",
            "-q",
            "-d",
            str(wheels),
            *PACKAGES,
        ],
        check=False,
        capture_output=True,
    )
    for archive in sorted(wheels.glob("*")):
        target = folder / archive.stem
        if archive.suffix == ".whl":
            with zipfile.ZipFile(archive) as wheel:
                wheel.extractall(target)
        else:
            with contextlib.suppress(Exception):
                shutil.unpack_archive(str(archive), str(target))
    shutil.rmtree(wheels, ignore_errors=True)
    return folder


# as installed: bytecode written and read (PYTHONDONTWRITEBYTECODE would have an
# edited checkout compile its changed modules in every timed run)
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def timed(
    command: list[str], cwd: Path | None = None, statuses: tuple[int, ...] = (0, 1)
) -> float:
    """Seconds of one process, which must end with one of `statuses`."""
    started = time.perf_counter()
    done = subprocess.run(command, cwd=cwd, capture_output=True, check=False, env=ENV)
    seconds = time.perf_counter() - started
    if done.returncode not in statuses:
        shown = " ".join(command[:5])
        raise SystemExit(
            f"{shown} ... exited {done.returncode}:\n{done.stderr.decode()[-2000:]}"
        )
    return seconds


def measure(
    name: str, files: list[Path], msgs: list[Path], asserted: bool, work: Path
) -> dict[str, object]:
    """`msgs`: the workload's interface folders; `asserted`: its files carry the
    tests' assertions, which the run must meet exactly."""
    lines = sum(f.read_bytes().count(b"\n") for f in files)
    parse = parse_seconds([f.read_bytes() for f in files])
    config = Config(root=work, msg_paths=tuple(msgs))
    check_paths(files, config)  # warm imports and machine caches
    started = time.perf_counter()
    found = check_paths(files, config)
    inprocess = time.perf_counter() - started
    if asserted:
        verify(files, found.diagnostics, None)
    statuses = (FOUND,) if asserted else (0, FOUND)
    args = [str(f) for f in files] + [a for m in msgs for a in ("--msg-path", str(m))]
    command = [
        sys.executable,
        "-m",
        "robotfix",
        "check",
        "--no-cache",
        "--format",
        "concise",
        *args,
    ]
    one = statistics.median(
        timed([*command, "-j", "1"], work, statuses) for _ in range(3)
    )
    every = statistics.median(timed(command, work, statuses) for _ in range(3))
    peak = robotfix_peak_mb(args, work)
    warm = None
    if len(files) > 100:  # "on every save": a second run with nothing changed
        cached = [
            sys.executable,
            "-m",
            "robotfix",
            "check",
            "--format",
            "concise",
            *args,
        ]
        timed(cached, work, statuses)
        warm = timed(cached, work, statuses)
    mypy = mypy_checked = None
    if _has_module("mypy"):
        mypy, mypy_checked = run_mypy(files, work / f"mypy-{len(files)}")
    return {
        "name": name,
        "files": len(files),
        "lines": lines,
        "parse": parse,
        "inprocess": inprocess,
        "process": one,
        "parallel": every,
        "mypy": mypy,
        "mypy_checked": mypy_checked,
        "diagnostics": len(found.diagnostics),
        "peak": peak,
        "warm": warm,
        "mypy_warm": run_mypy(files, work / f"mypy-{len(files)}", warm=True)[0]
        if warm is not None and mypy is not None
        else None,
    }


def robotfix_peak_mb(args: list[str], work: Path) -> float:
    """Peak memory of one `robotfix check -j 1` process, as it reports itself."""
    script = (
        "import resource, sys\nfrom robotfix.cli import main\n"
        "code = main(sys.argv[1:])\n"
        "print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, file=sys.stderr)\n"
    )
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            script,
            "check",
            "--no-cache",
            "-j",
            "1",
            "--format",
            "concise",
            *args,
        ],
        cwd=work,
        capture_output=True,
        text=True,
        check=False,
    )
    return int(done.stderr.strip().splitlines()[-1]) / 1024


def mypy_checkable(files: list[Path], folder: Path) -> list[Path]:
    """The files without errors that stop mypy ("errors prevented further checking":
    Python 2 syntax, relative imports of the flattened copies), so that both tools
    are timed on files both can check."""
    kept = list(files)
    for attempt in range(20):
        blocked = _mypy_blocked(kept, folder / str(attempt))
        if not blocked:
            break
        kept = [f for i, f in enumerate(kept) if i not in blocked]
    return kept


def _mypy_blocked(files: list[Path], folder: Path) -> set[int]:
    copies = _copies(files, folder)
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "mypy",
            "--no-incremental",
            "--ignore-missing-imports",
            "--follow-imports=silent",
            "--cache-dir",
            str(folder / ".cache"),
            *copies,
        ],
        cwd=folder,
        capture_output=True,
        text=True,
        check=False,
    )
    if "prevented further checking" not in done.stdout:
        return set()
    return {int(m.group(1)) for m in re.finditer(r"^m(\d{5})_", done.stdout, re.M)}


def _copies(files: list[Path], folder: Path) -> list[str]:
    folder.mkdir(parents=True, exist_ok=True)
    copies = []
    for index, file in enumerate(files):
        copy = folder / f"m{index:05d}_{file.stem}.py"
        copy.write_bytes(file.read_bytes())
        copies.append(str(copy))
    return copies


def run_mypy(
    files: list[Path], folder: Path, warm: bool = False
) -> tuple[float | None, int | None]:
    """mypy, cold, on copies of the same files with unique names: mypy stops at
    "duplicate module named" (many setup.py, the seeds' buggy.py/fixed.py) otherwise.
    Returns the time and how many files mypy says it checked."""
    copies = _copies(files, folder)
    mode = ["--incremental"] if warm else ["--no-incremental"]
    command = [
        sys.executable,
        "-m",
        "mypy",
        *mode,
        "--ignore-missing-imports",
        "--follow-imports=silent",
        "--cache-dir",
        str(folder / ".cache"),
        *copies,
    ]
    if warm:  # fill the cache first; time the second run
        subprocess.run(command, cwd=folder, capture_output=True, check=False)
    started = time.perf_counter()
    done = subprocess.run(
        command, cwd=folder, capture_output=True, text=True, check=False
    )
    seconds = time.perf_counter() - started
    last = (done.stdout.strip().splitlines() or [""])[-1]
    match = re.search(
        r"(\d+) source files?\)|no issues found in (\d+) source files?", last
    )
    checked = int(next(g for g in match.groups() if g)) if match else None
    return seconds, checked


def parse_seconds(texts: list[bytes]) -> float:
    """Python's own ast.parse over the texts: the floor every checker stands on."""
    started = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for text in texts:
            with contextlib.suppress(SyntaxError, ValueError):
                ast.parse(text)
    return time.perf_counter() - started


def _has_module(name: str) -> bool:
    from importlib.util import find_spec

    return find_spec(name) is not None


def render(
    rows: list[dict[str, object]], startup: float, peak: float, real: list[Path]
) -> str:
    cpu = platform.processor() or platform.machine()
    with contextlib.suppress(OSError):
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    out = [
        "# Performance",
        "",
        f"Measured {datetime.date.today()} with `python benchmarks/peers.py` on {cpu}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}, "
        f"RobotFix {__version__}. Real code: ros-rclpy, catkin-pkg and rospkg from PyPI"
        + (f", plus {', '.join(str(r) for r in real[:-1])}" if len(real) > 1 else "")
        + ".",
        "",
        "| workload | files | lines | ast.parse | RobotFix in-process | ratio | "
        "RobotFix process -j 1 | RobotFix process -j all | mypy process | "
        "mypy / RobotFix |",
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for r in rows:
        parse, inproc, proc = (
            float(r["parse"]),
            float(r["inprocess"]),
            float(r["process"]),
        )  # type: ignore[arg-type]
        mypy = r["mypy"]
        mypy_cell = f"{mypy:.2f} s" if isinstance(mypy, float) else "n/a"
        if isinstance(mypy, float) and r["mypy_checked"] != r["files"]:
            mypy_cell += f" ({r['mypy_checked']} files checked)"
        speedup = f"{mypy / proc:.1f}x" if isinstance(mypy, float) else "n/a"
        out.append(
            f"| {r['name']} | {r['files']} | {r['lines']:,} | {parse:.2f} s | "
            f"{inproc:.2f} s | {inproc / parse:.1f}x | {proc:.2f} s | "
            f"{float(r['parallel']):.2f} s | {mypy_cell} | {speedup} |"  # type: ignore[arg-type]
        )
    out += [""]
    for r in rows:
        out.append(
            f"- {r['name']}: RobotFix peak memory {float(r['peak']):.0f} MB "  # type: ignore[arg-type]
            f"(-j 1)."
        )
        if r["warm"] is not None:
            mypy_warm = r["mypy_warm"]
            out.append(
                f"  Second run with nothing changed (the every-save case): RobotFix "
                f"{float(r['warm']):.2f} s with its cache, mypy "  # type: ignore[arg-type]
                + (
                    f"{mypy_warm:.2f} s incremental."
                    if isinstance(mypy_warm, float)
                    else "n/a."
                )
            )
    out += [
        "",
        f"`robotfix --version`: {startup * 1000:.0f} ms (median of 10). "
        f"Peak memory of any process of the run, mypy's included: {peak:.0f} MB.",
        "",
        "Targets (issue 5): unannotated real code within 5x of ast.parse (the ratio "
        "column); the 10,000-line annotated file under 5 s; 10x faster than mypy; "
        "`--version` under 150 ms; peak memory under 500 MB.",
        "",
    ]
    return "\n".join(out)


if __name__ == "__main__":
    main()
