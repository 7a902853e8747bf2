"""The workspace analysis runs beside flake8's checks, never inside one.

With ``--jobs`` above 1 flake8 checks files in a pool of worker processes. If the
checker analysed the workspace there (as it does with ``-j1``), the first worker to
need the findings would analyse while every other worker waited on the cache lock
for its first file: the analysis would sit on the critical path, alone on one core.

Instead, during ``Manager.run_parallel`` the analysis runs beside the workers, while their
checkers report nothing (:func:`deferred`). Where the run may fork (as for ``-j1`` below), a
child forked before the pool starts analyses, using every core (:mod:`.forked`: groups of
modules in processes of their own), and hands each file's results back (it also leaves the
report in the cache); otherwise the main process analyses in a thread it starts right after the
pool has started its workers (so no worker inherits a half-done analysis or a held lock). Once
the pool is done, the main process adds each file's ROS results to the results the workers sent
back — the same code, line, column and text the checker would have yielded, with the
``noqa`` line flake8's file processor gives — before flake8 filters and reports them as usual.

The analysis is the run's critical path: it takes longer than the workers' share of the
checks, and with ``--jobs=auto`` there is one worker per core, so it competes with them for the
cores. Each worker therefore lowers its own priority (:data:`WORKER_NICENESS`) when it first
defers a file to the main process; the analysis keeps the cores and the run ends sooner, the
workers using what the analysis leaves.

Works with the fork, spawn and forkserver start methods (spawned workers learn of
the run from :data:`DEFER_ENV`, which only a pool worker heeds) and with flake8 4.0.1
(``Manager.checkers``) to 7.x (``Manager.filenames`` / ``Manager.results``).

With ``-j1`` (and a run of one file) flake8 checks the files in its own process. Where the
machine has a second core and the report is not kept yet, a forked child process analyses
meanwhile (with the cores flake8 leaves it) and hands each file's results back; the checkers
report nothing, and once flake8 is done the main process adds them the same way. A cold or
edited run then costs about the longer of the two instead of their sum — pre-commit's run of
the few files a commit changes included: flake8's own checks of them overlap the analysis.
When the child could not hand its results back (it died, or failed), the main process
analyses itself: the results never depend on the child.
"""
from __future__ import annotations

import contextlib
import functools
import multiprocessing
import os
import pickle
import threading
from typing import Any, Callable, Iterator

from . import forked

#: Set by the main process for the workers of its pool: "the ROS results are mine".
DEFER_ENV = "ROSGRAPH_DEFERRED_TO"
#: flake8's codes for a file it could not read or parse: the plugin never runs there.
_UNCHECKED = frozenset({"E902", "E999"})

#: Added to a pool worker's nice value while the main process analyses (see the module docstring).
WORKER_NICENESS = 5

_deferring = False  # in the main process during run_parallel (forked workers inherit it)
_yielded = False  # this worker process has lowered its priority
_analysis_processes: int | None = None  # in a child analysing beside flake8's checks: its share

Results = list  # of (line, column, text) as a checker yields them


def deferred() -> bool:
    """Whether ROS results of this process's checkers are added by the main process."""
    return _deferring or (os.environ.get(DEFER_ENV) is not None
                          and multiprocessing.parent_process() is not None)


def yield_to_analysis() -> None:
    """In a pool worker whose ROS results the main process adds: lower this process's priority,
    once, so that the analysis the main process runs meanwhile keeps its core. Never in flake8's
    main process, which runs the analysis itself."""
    global _yielded
    if _yielded or multiprocessing.parent_process() is None:
        return
    _yielded = True
    with contextlib.suppress(AttributeError, OSError):  # no os.nice (Windows), or refused
        os.nice(WORKER_NICENESS)


def install(results_of: Callable[[str], Results], wanted: Callable[[], bool],
            beside: Callable[[list[str]], bool]) -> None:
    """Wrap ``Manager.run_parallel`` and ``Manager.run_serial``: ``results_of(filename)`` is what
    the checker would yield for a file; ``wanted()`` says whether the current run needs any
    of it; ``beside(filenames)`` whether a child process may analyse while ``-j1`` checks."""
    from flake8 import checker

    serial = checker.Manager.run_serial
    if not getattr(serial, "_rosgraph_hook", False):
        @functools.wraps(serial)
        def run_serial(self: Any) -> Any:
            filenames = list(_checked_files(self))
            if _deferring or not wanted() or not beside(filenames):
                return serial(self)
            return _run_serial_beside(self, serial, results_of, filenames)

        run_serial._rosgraph_hook = True  # type: ignore[attr-defined]
        checker.Manager.run_serial = run_serial

    original = checker.Manager.run_parallel
    if getattr(original, "_rosgraph_hook", False):
        return

    @functools.wraps(original)
    def run_parallel(self: Any) -> Any:
        if not wanted():
            return original(self)
        return _run_parallel(self, original, results_of, beside)

    run_parallel._rosgraph_hook = True  # type: ignore[attr-defined]
    checker.Manager.run_parallel = run_parallel


class _Analysis:
    """The ROS results of every checked file, computed in a background thread."""

    def __init__(self, filenames: list[str], results_of: Callable[[str], Results]) -> None:
        self.filenames = filenames
        self.results_of = results_of
        self.results: dict[str, Results] = {}
        self.error: BaseException | None = None
        self._thread = threading.Thread(target=self._run, name="rosgraph-analysis", daemon=True)

    def start(self) -> None:
        if self._thread.ident is None:
            self._thread.start()

    def wait(self) -> dict[str, Results]:
        self.start()
        self._thread.join()
        if self.error is not None:
            raise self.error
        return self.results

    def _run(self) -> None:
        try:
            for filename in self.filenames:
                self.results[filename] = self.results_of(filename)
        except BaseException as exc:  # re-raised in the main thread (--rosgraph-debug)
            self.error = exc


def _run_parallel(manager: Any, original: Callable[[Any], Any], results_of: Callable[[str], Results],
                  beside: Callable[[list[str]], bool]) -> Any:
    from flake8 import checker

    filenames = list(_checked_files(manager))
    child = analysis = None
    if threading.active_count() == 1 and beside(filenames):
        child = _analyse_in_child(filenames, results_of, forked.cores())  # before the pool's threads
    else:
        analysis = _Analysis(filenames, results_of)
    make_pool = checker._try_initialize_processpool

    def pool_then_analysis(*args: Any, **kwargs: Any) -> Any:
        pool = make_pool(*args, **kwargs)
        if analysis is not None:
            analysis.start()
        return pool

    previous = os.environ.get(DEFER_ENV)
    os.environ[DEFER_ENV] = str(os.getpid())
    checker._try_initialize_processpool = pool_then_analysis
    try:
        with _deferring_to(child):
            outcome = original(manager)
    finally:
        checker._try_initialize_processpool = make_pool
        if previous is None:
            os.environ.pop(DEFER_ENV, None)
        else:
            os.environ[DEFER_ENV] = previous
    _add_results(manager, _results_after(child, filenames, results_of) if analysis is None else analysis.wait())
    return outcome


def _run_serial_beside(manager: Any, original: Callable[[Any], Any], results_of: Callable[[str], Results],
                       filenames: list[str]) -> Any:
    child = _analyse_in_child(filenames, results_of, forked.cores() - 1)  # one core checks the files
    with _deferring_to(child):
        outcome = original(manager)
    _add_results(manager, _results_after(child, filenames, results_of))
    return outcome


def _analyse_in_child(filenames: list[str], results_of: Callable[[str], Results],
                      processes: int) -> forked.ForkedJobs:
    """Fork a child that works out each file's results with up to ``processes`` processes
    (:mod:`.forked`) and hands them back, pickled (they pass only from this process's child to
    it); it never returns into flake8."""
    def work(_job: int) -> bytes:
        global _analysis_processes
        _analysis_processes = max(1, processes)
        return pickle.dumps({filename: results_of(filename) for filename in filenames})

    return forked.ForkedJobs.start([0], work, 1)


def _results_after(child: forked.ForkedJobs, filenames: list[str],
                   results_of: Callable[[str], Results]) -> dict[str, Results]:
    """Once the child is done, each file's results: those it handed back (or, when it could
    not, analysed here: the results never depend on the child)."""
    sent = child.collect().get(0)
    if sent is not None:
        return pickle.loads(sent)
    return {filename: results_of(filename) for filename in filenames}


@contextlib.contextmanager
def _deferring_to(child: forked.ForkedJobs | None) -> Iterator[None]:
    """flake8's checkers leave their ROS results to this process while the block runs (the
    analysis runs in ``child``, or in a thread); an interrupted run stops the child."""
    global _deferring
    _deferring = True
    try:
        yield
    except BaseException:
        _stop(child)
        raise
    finally:
        _deferring = False


def _stop(child: forked.ForkedJobs | None) -> None:
    """flake8 was interrupted: the child's work is not wanted any more."""
    if child is not None:
        child.stop()


def analysis_processes() -> int:
    """The processes this process's analysis may use (:mod:`.forked`): every core, but the one
    flake8 checks files on while a ``-j1`` run's child analyses beside it."""
    return _analysis_processes or forked.cores()


def _checked_files(manager: Any) -> Iterator[str]:
    if hasattr(manager, "filenames"):  # flake8 >= 5
        yield from manager.filenames
    else:  # flake8 4: FileChecker objects
        yield from (c.filename for c in manager.checkers)


def _result_lists(manager: Any) -> Iterator[tuple[str, list]]:
    """``(filename, the list flake8 reports from)`` for every checked file."""
    checkers = getattr(manager, "checkers", None)
    if checkers is not None and not hasattr(manager, "filenames"):  # flake8 4
        for file_checker in checkers:
            yield file_checker.display_name, file_checker.results
    else:
        for entry in manager.results:
            yield entry[0], entry[1]


def _add_results(manager: Any, found: dict[str, Results]) -> None:
    for filename, results in _result_lists(manager):
        mine = found.get(filename)
        if not mine or any(result[0] in _UNCHECKED for result in results):
            continue
        processor = _processor(filename, manager.options)
        if processor is not None and processor.should_ignore_file():  # "# flake8: noqa"
            continue
        for line, column, text in mine:
            code, message = text.split(" ", 1)
            results.append((code, line, column, message, _noqa_line(processor, line)))


def _processor(filename: str, options: Any) -> Any:
    from flake8.processor import FileProcessor

    try:
        return FileProcessor(filename, options)
    except Exception:  # flake8 reported why (E902); a missing noqa line is all it costs
        return None


def _noqa_line(processor: Any, line: int) -> str | None:
    if processor is None:
        return None
    try:
        return processor.noqa_line_for(line)
    except Exception:  # the tokenizer's view of a broken file
        return None
