"""A whole run: find the files, reuse cached results, check the rest (in parallel
processes with -j), and gather the diagnostics in a deterministic order.
"""

from __future__ import annotations

import multiprocessing
import os
import time
import traceback
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

from robotfix import messages
from robotfix.annotations.units import save_cache as save_unit_cache
from robotfix.api import (
    InternalError,
    Result,
    catalog_problems,
    check_file,
    finish,
    interface_files,
    python_files,
    ros_interface_folders,
)
from robotfix.cache import ResultCache, run_key
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.ros.catalog import MsgCatalog

MIN_PARALLEL = 16  # fewer files are checked faster in one process than by a pool


@dataclass
class FileResult:
    path: str
    diagnostics: list[Diagnostic] = field(default_factory=list)
    error: InternalError | None = None
    types: list[str] = field(default_factory=list)  # message types it looked up
    fingerprint: str = ""  # the catalog's fingerprint of `types`, as the check saw it


def check_paths(
    paths: list[Path],
    config: Config,
    progress: Callable[[int, int, str], None] | None = None,
    jobs: int = 1,
    use_cache: bool = False,
) -> Result:
    """Check every Python file under `paths`; interface files come from the msg paths
    and from the msg/srv/action folders of ROS packages under `paths`."""
    started = time.perf_counter()
    result = Result()
    folders = list(config.msg_paths) + ros_interface_folders(paths)
    catalog = _catalog(folders, config)
    result.diagnostics.extend(catalog_problems(catalog))
    files = python_files(paths, config)
    result.files = len(files)
    result.checked = [str(file) for file in files]
    cache = (
        ResultCache(
            config.cache_dir or config.root / ".robotfix_cache", run_key(config)
        )
        if use_cache
        else None
    )
    todo: list[tuple[Path, bytes]] = []
    for index, file in enumerate(files, start=1):
        try:
            data = file.read_bytes()
        except OSError as err:
            reason = f"cannot read: {err.strerror}"
            result.diagnostics.append(messages.unreadable(str(file), reason))
            continue
        cached = cache.get(file, data, config, catalog) if cache else None
        if cached is not None:
            result.diagnostics.extend(cached)
            result.from_cache += 1
            if progress is not None:
                progress(index, len(files), str(file))
        else:
            todo.append((file, data))
    done = len(files) - len(todo)
    contents = dict(todo)
    for outcome in _check_all(todo, folders, config, catalog, jobs):
        done += 1
        if progress is not None:
            progress(done, len(files), outcome.path)
        result.diagnostics.extend(outcome.diagnostics)
        if outcome.error is not None:
            result.internal_errors.append(outcome.error)
        elif cache is not None:
            cache.put(
                Path(outcome.path),
                contents[Path(outcome.path)],
                config,
                outcome.diagnostics,
                outcome.types,
                outcome.fingerprint,
            )
    result.diagnostics = finish(result.diagnostics)
    if cache is not None:
        cache.prune(paths, files)
        cache.save()
    catalog.save()
    save_unit_cache()
    result.seconds = time.perf_counter() - started
    return result


def _catalog(folders: list[Path], config: Config) -> MsgCatalog:
    return MsgCatalog(
        interface_files(folders), rep103=config.rep103, distro=config.ros_distro
    )


def _check_all(
    todo: list[tuple[Path, bytes]],
    folders: list[Path],
    config: Config,
    catalog: MsgCatalog,
    jobs: int,
) -> list[FileResult]:
    if jobs <= 1 or len(todo) < MIN_PARALLEL:
        return [_check_one(path, data, catalog, config) for path, data in todo]
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    with ProcessPoolExecutor(
        max_workers=min(jobs, len(todo)),
        mp_context=multiprocessing.get_context(method),
        initializer=_start_worker,
        initargs=(folders, config),
    ) as pool:
        chunk = max(1, len(todo) // (jobs * 4))
        return list(pool.map(_worker_check, todo, chunksize=chunk))


def _check_one(
    path: Path, data: bytes, catalog: MsgCatalog, config: Config
) -> FileResult:
    catalog.touched = set()
    try:
        found = check_file(str(path), data, catalog, config.ignored_codes(path))
        types = sorted(catalog.touched)
        catalog.touched = None
        return FileResult(
            str(path), found, None, types, catalog.fingerprint_types(types)
        )
    except Exception as err:  # a fault of ours: report it, go on with the others
        summary = f"{type(err).__name__}: {err}"
        return FileResult(
            str(path), [], InternalError(str(path), summary, traceback.format_exc())
        )
    finally:
        catalog.touched = None


_WORKER: tuple[MsgCatalog, Config] | None = None


def _start_worker(folders: list[Path], config: Config) -> None:
    global _WORKER
    _WORKER = (_catalog(folders, config), config)


def _worker_check(item: tuple[Path, bytes]) -> FileResult:
    assert _WORKER is not None
    catalog, config = _WORKER
    return _check_one(item[0], item[1], catalog, config)


def default_jobs() -> int:
    return (
        len(os.sched_getaffinity(0))
        if hasattr(os, "sched_getaffinity")
        else (os.cpu_count() or 1)
    )
