"""C++ nodes' parameters (issue 23, section 1) against launch files and parameter
files: the workspaces under tests/cases/cpp_params/ (after ros2/demos' image_tools
and navigation2's servers and nav2_params.yaml), with inline expectations in
their launch and YAML files (strict for the parameter rules), and the reading of
C++ declarations on its own."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from robotfix.api import check_paths
from robotfix.config import Config
from robotfix.cppparams import CppParams, ros2_type
from robotfix.ros.graph.cpp import read_cpp
from robotfix.testing.expectations import compare_files

CASES = Path(__file__).parent / "cases" / "cpp_params"
SUFFIXES = (".py", ".yaml", ".xml", ".launch")
PARAMETER_RULES = {"RF101", "RF401", "RF601", "RF602", "RF004"}


@pytest.mark.parametrize(
    "workspace", sorted(p for p in CASES.iterdir() if p.is_dir()), ids=lambda p: p.name
)
def test_cpp_parameters_of_a_workspace(workspace: Path) -> None:
    found = check_paths([workspace], Config(root=workspace)).diagnostics
    found = [d for d in found if d.code in PARAMETER_RULES]
    files = sorted(p for p in workspace.rglob("*") if p.name.endswith(SUFFIXES))
    problems = compare_files(files, found)
    assert not problems, "\n".join(problems)


def test_a_cpp_declarations_type_is_certain_only_where_rclcpps_is() -> None:
    source = b"""
class Driver : public rclcpp::Node {
  Driver() : Node("driver") {
    declare_parameter<double>("a", 1);
    declare_parameter("b", 0.5);
    declare_parameter("c", -3);
    declare_parameter("d", rclcpp::ParameterValue{2.0});
    declare_parameter("e", std::string("map"));
    declare_parameter<std::vector<double>>("f", {1.0});
    declare_parameter("g", some_default_);
    declare_parameter<rclcpp::Duration>("h", 1.0);
    declare_parameter("i", rclcpp::ParameterType::PARAMETER_INTEGER_ARRAY);
    declare_parameter("j", rclcpp::PARAMETER_DOUBLE, descriptor);
  }
};
"""
    graph = read_cpp(source)
    types = {
        e.name: ros2_type(e.types[0]) if e.types else None for e in graph.endpoints
    }
    assert types == {
        "a": "double",
        "b": "double",
        "c": "integer",
        "d": "double",
        "e": "string",
        "f": "double_array",
        "g": None,
        "h": None,
        "i": "integer_array",
        "j": "double",
    }
    dynamic = read_cpp(source.replace(b"{\n  Driver", b"{ // dynamic_typing\n  D"))
    assert all(not e.types for e in dynamic.endpoints)


@pytest.mark.parametrize(
    "opening",
    [
        "rclcpp::NodeOptions().allow_undeclared_parameters(true)",
        'declare_parameter(name_ + ".x", 1.0)',
        'declare_parameter_if_not_declared(shared_from_this(), name_ + ".x", 1.0)',
        "loader_.createUniqueInstance(type)",
        "params_ = std::make_shared<ParamListener>(node)",
    ],
)
def test_code_that_may_declare_more_keeps_rf601_silent(opening: str) -> None:
    source = f"""
class Driver : public rclcpp::Node {{
  Driver() : Node("driver") {{
    declare_parameter("speed", 0.5);
    auto x = {opening};
  }}
}};
""".encode()
    summary = CppParams({"driver.cpp": read_cpp(source)}).summaries[0]
    assert "Driver" in summary.open_owners
    without = source.replace(f"auto x = {opening};".encode(), b"")
    closed = CppParams({"driver.cpp": read_cpp(without)})
    assert "Driver" not in closed.summaries[0].open_owners


def test_a_node_class_of_another_package_may_declare_more() -> None:
    source = b"""
class Smoother : public nav2_util::LifecycleNode {
  Smoother() : nav2_util::LifecycleNode("velocity_smoother") {
    declare_parameter("smoothing_frequency", 20.0);
  }
};
"""
    summary = CppParams({"smoother.cpp": read_cpp(source)}).summaries[0]
    assert summary.node_names == {"Smoother": ["velocity_smoother"]}
    assert "Smoother" in summary.open_owners


def test_nav2s_helper_declares_on_the_node_it_is_handed() -> None:
    source = b"""
class Smoother : public rclcpp_lifecycle::LifecycleNode {
  Smoother() : LifecycleNode("velocity_smoother") {}
  void on_configure() {
    auto node = shared_from_this();
    declare_parameter_if_not_declared(node, "odom_duration", ParameterValue(0.1));
    declare_parameter_if_not_declared(
      node, "max_velocity", rclcpp::ParameterValue(std::vector<double>{0.5, 0.0}));
    nav2_util::declare_parameter_if_not_declared(other_, "scale", 1.0);
  }
};
"""
    summary = CppParams({"smoother.cpp": read_cpp(source)}).summaries[0]
    found = {(d.owner, d.name, d.type) for d in summary.decls}
    assert found == {
        ("Smoother", "odom_duration", "double"),
        ("Smoother", "max_velocity", "double_array"),
        ("Smoother.other_", "scale", "double"),
    }
    assert not summary.open_owners


def test_a_tests_nodes_are_not_the_nodes_named_so(tmp_path: Path) -> None:
    package = tmp_path / "tests" / "driver"
    (package / "test").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>driver</name></package>")
    source = b"""
class Driver : public rclcpp::Node {
  Driver() : Node("driver") { declare_parameter("speed", 1); }
};
"""
    found = CppParams(
        {
            str(package / "src" / "driver.cpp"): read_cpp(source),
            str(package / "test" / "test_driver.cpp"): read_cpp(source),
        }
    )
    assert [s.path for s in found.summaries] == [str(package / "src" / "driver.cpp")]
    assert found.names == {"driver"}


def test_a_fault_on_one_cpp_file_is_its_internal_error(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import robotfix.cppparams as cppparams

    real = cppparams._summary

    def broken(path: str, graph: object) -> object:
        if path.endswith("velocity_smoother.cpp"):
            raise RuntimeError("boom")
        return real(path, graph)  # type: ignore[arg-type]

    monkeypatch.setattr(cppparams, "_summary", broken)
    workspace = CASES / "nav_ws"
    result = check_paths([workspace], Config(root=workspace))
    assert [Path(e.path).name for e in result.internal_errors] == [
        "velocity_smoother.cpp"
    ]
    found = {
        (Path(d.path).name, d.span.line, d.code)
        for d in result.diagnostics
        if d.code in PARAMETER_RULES
    }
    assert found == {  # the controller server's, none of the smoother's
        ("nav2_params.yaml", 4, "RF401"),
        ("navigation_launch.py", 28, "RF401"),
    }


def test_a_cached_run_sees_an_edited_cpp_declaration(tmp_path: Path) -> None:
    """The C++ declarations (and the build files that map executables to them)
    join the parameter check's cache key."""
    shutil.copytree(CASES / "image_ws", tmp_path / "ws")
    workspace = tmp_path / "ws"
    config = Config(root=workspace)

    def codes() -> list[tuple[str, str, int]]:
        found = check_paths([workspace], config, use_cache=True).diagnostics
        return sorted(
            (d.code, Path(d.path).name, d.span.line)
            for d in found
            if d.code in PARAMETER_RULES
        )

    first = codes()
    assert ("RF401", "camera.yaml", 3) in first and codes() == first
    source = workspace / "image_tools" / "src" / "cam2image.cpp"
    text = source.read_text()
    source.write_text(text.replace('("frequency", 30.0)', '("frequency", 30)'))
    second = codes()
    assert ("RF401", "camera.yaml", 3) not in second
    assert ("RF401", "camera.yaml", 11) in second  # `frequency: 0.5` now
    # a launch file's own part (kept apart since fix/graphcache23) sees it too
    assert ("RF401", "camera.launch.py", 19) in first
    assert ("RF401", "camera.launch.py", 19) not in second  # `frequency: 15` fits
    assert ("RF401", "camera.launch.py", 33) in second  # `frequency: 1.0` does not
    cmake = workspace / "image_tools" / "CMakeLists.txt"
    built = cmake.read_text().replace("EXECUTABLE cam2image", "EXECUTABLE cam")
    cmake.write_text(built)
    assert ("RF401", "camera.launch.py", 20) not in codes()  # `cam2image`: no code


def test_a_packages_cmake_targets_are_read_once_a_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The C++ nodes' parameters and the graph both ask what each launch entry's
    executable is built from: a package's CMakeLists.txt is read once a run (it
    was read for each, and each executable's sources and headers found), and
    again in the next run (the memos are the run's)."""
    from robotfix import graphcheck
    from robotfix.ros import executables

    workspace = tmp_path / "image_ws"
    shutil.copytree(CASES / "image_ws", workspace)
    read: list[str] = []
    real = executables._cmake_targets
    monkeypatch.setattr(
        executables,
        "_cmake_targets",
        lambda package: read.append(package.name) or real(package),
    )
    built: list[str] = []  # what an executable is built from: found once too
    files = graphcheck.cpp_executable_files
    monkeypatch.setattr(
        graphcheck,
        "cpp_executable_files",
        lambda package, name, memo: built.append(name) or files(package, name, memo),
    )
    config = Config(root=workspace)

    def codes() -> list[tuple[str, str, int]]:
        found = check_paths([workspace], config).diagnostics
        return sorted(
            (d.code, Path(d.path).name, d.span.line)
            for d in found
            if d.code in PARAMETER_RULES
        )

    first = codes()
    assert read == ["image_tools"] and sorted(built) == ["cam2image", "showimage"]
    assert ("RF401", "camera.launch.py", 19) in first
    cmake = workspace / "image_tools" / "CMakeLists.txt"
    cmake.write_text(
        cmake.read_text().replace("EXECUTABLE cam2image", "EXECUTABLE cam")
    )
    read.clear()
    second = codes()
    assert read == ["image_tools"]
    assert ("RF401", "camera.launch.py", 19) not in second  # `cam2image`: no code
