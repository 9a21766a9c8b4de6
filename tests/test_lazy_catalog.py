"""A cached run's catalog reads a type from its own file when it is looked up
(`MsgCatalog.preload_outline`), and gives what the full load gives: the same spec
for every type, whatever was looked up before, and the same packages."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from robotfix.ros.catalog import MsgCatalog

CASES = Path(__file__).parent / "cases"
SUFFIXES = (".msg", ".srv", ".action", ".idl")


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def _files(tmp_path: Path) -> list[Path]:
    """The project's cases (many redefine a standard type, some twice: the first
    wins) and a package whose annotations reach into another file's type."""
    (tmp_path / "robot" / "package.xml").parent.mkdir(parents=True)
    (tmp_path / "robot" / "package.xml").write_text(
        "<package><name>robot</name></package>"
    )
    _write(
        tmp_path / "robot" / "msg" / "Wheel.msg",
        'float64 speed  # [m/s]\nfloat64 angle\n#RobotFix# Unit(angle) == "rad"\n',
    )
    _write(
        tmp_path / "robot" / "msg" / "Drive.msg",
        "uint8 MAX=3\nWheel left\nWheel right\nUnknownThing odd\n"
        '#RobotFix# left.speed <= MAX and Unit(right.angle) == "deg"\n'
        "float64 rate_hz\n",
    )
    _write(
        tmp_path / "robot" / "srv" / "Stop.srv",
        "Wheel wheel\n---\nbool ok\ngeometry_msgs/Twist last\n",
    )
    found = [p for p in sorted(CASES.rglob("*")) if p.suffix in SUFFIXES]
    return found + [p for p in sorted(tmp_path.rglob("*")) if p.suffix in SUFFIXES]


@pytest.mark.parametrize("suffixes", [False, True])
def test_a_type_read_alone_is_the_type_read_with_all(
    tmp_path: Path, suffixes: bool
) -> None:
    files = _files(tmp_path)
    full = MsgCatalog(files, unit_suffixes=suffixes)
    full.load()
    outline = full.outline()
    assert outline is not None and len(outline) > 20
    names = [*sorted(full._specs), "geometry_msgs/Pose", "nope/Nope"]
    assert "robot/Drive" in names and "robot/Stop_Request" in names
    want = {name: repr(full.lookup(name)) for name in names}
    packages = {name.split("/")[0] for name in names}
    for name in names:  # each alone: only its own files are read
        lazy = MsgCatalog(files, unit_suffixes=suffixes)
        lazy.preload_outline(outline)
        assert repr(lazy.lookup(name)) == want[name], name
    lazy = MsgCatalog(files, unit_suffixes=suffixes)
    lazy.preload_outline(outline)
    order = list(names)
    random.Random(13).shuffle(order)
    assert [repr(lazy.lookup(n)) for n in order] == [want[n] for n in order]
    assert {p: lazy.has_package(p) for p in packages} == {
        p: full.has_package(p) for p in packages
    }
    # what needs every file (problems, refined types) loads them all, as before
    assert lazy.types_in(str(files[-1])) == full.types_in(str(files[-1]))
    assert repr(lazy.problems) == repr(full.problems)
    assert repr(lazy.refined_specs()) == repr(full.refined_specs())


def test_one_lookup_reads_only_the_files_it_needs(tmp_path: Path) -> None:
    files = _files(tmp_path)
    full = MsgCatalog(files)
    full.load()
    lazy = MsgCatalog(files)
    lazy.preload_outline(full.outline() or [])
    read: list[Path] = []
    real = lazy._read
    lazy._read = lambda path: read.append(path) or real(path)  # type: ignore[method-assign]
    assert repr(lazy.lookup("robot/Drive")) == repr(full.lookup("robot/Drive"))
    assert sorted(p.name for p in read) == ["Drive.msg", "Wheel.msg"]


def test_a_file_changed_since_its_outline_falls_back_to_the_full_load(
    tmp_path: Path,
) -> None:
    files = _files(tmp_path)
    full = MsgCatalog(files)
    full.load()
    outline = full.outline() or []
    wheel = tmp_path / "robot" / "msg" / "Wheel.msg"
    wheel.write_text("float64 speed  # [km/h]\n")
    lazy = MsgCatalog(files)
    lazy.preload_outline(outline)
    fresh = MsgCatalog(files)
    fresh.load()
    assert repr(lazy.lookup("robot/Wheel")) == repr(fresh.lookup("robot/Wheel"))
    assert repr(lazy.lookup("robot/Drive")) == repr(fresh.lookup("robot/Drive"))
    assert repr(lazy.problems) == repr(fresh.problems)


def test_digests_from_an_earlier_run_give_the_fingerprints_a_full_load_gives(
    tmp_path: Path,
) -> None:
    """A cached run's catalog makes each file's fingerprint from the digests an
    earlier run kept (each type's fields walked once, `MsgCatalog._closure`): the
    same as a catalog that reads the files, for any set of names, a name spelled
    with `/msg/` or not known included."""
    files = _files(tmp_path)
    full = MsgCatalog(files)
    full.load()
    types = [*sorted(full._specs)[:60], "geometry_msgs/msg/Pose", "nope/Nope"]
    rng = random.Random(7)
    asked = [rng.sample(types, rng.randint(0, 12)) for _ in range(12)]
    asked += [["robot/Drive"], ["robot/Drive", "robot/Wheel"], types]
    # each by a catalog of its own, which looks every type up
    want = [MsgCatalog(files).fingerprint_types(list(a)) for a in asked]
    for names in asked:
        full.fingerprint_types(names)  # the digests an earlier run kept
    for order in (asked, asked[::-1]):
        kept = MsgCatalog(files)
        kept.preload_digests(full.digest_table())
        got = {tuple(a): kept.fingerprint_types(list(a)) for a in order}
        assert [got[tuple(a)] for a in asked] == want
        assert kept._closures  # the kept digests answered


@pytest.mark.parametrize("lazy", [False, True])
def test_has_package_answers_as_a_scan_of_every_name(
    tmp_path: Path, lazy: bool
) -> None:
    """`has_package` keeps the names' packages in a set; it answers what a scan of
    every declared and standard name for the prefix `package/` answers, before and
    after lookups add names, for a spelled package, a prefix, a path and nothing."""
    files = _files(tmp_path)
    full = MsgCatalog(files)
    full.load()
    catalog = MsgCatalog(files)
    if lazy:
        catalog.preload_outline(full.outline() or [])
    asked = ["robot", "std_msgs", "geometry_msgs", "rob", "", "robot/msg", "nothing"]
    asked += ["diagnostic_msgs", "shape_msgs", "stereo_msgs", "trajectory_msgs"]

    def scanned(package: str) -> bool:
        prefix = package + "/"
        names = (*catalog._specs, *catalog._standard())
        return any(name.startswith(prefix) for name in names)

    for name in ["", "robot/Drive", "sensor_msgs/msg/Imu", "robot/msg/Wheel"]:
        if name:
            catalog.lookup(name)
        assert {p: catalog.has_package(p) for p in asked} == {
            p: scanned(p) for p in asked
        }
    assert catalog.has_package("robot") and not catalog.has_package("rob")
