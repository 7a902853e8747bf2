"""Independent jobs of one run in forked processes, when the run has cores to spare.

The analysis splits into jobs that read nothing of one another — the groups of Python
modules (:meth:`.Program.components`), each analysed on its own. On a machine with several
cores those can run side by side: the parent has read and parsed the workspace, and a child
forked from it sees all of that as it is (copy-on-write), takes jobs one at a time from a
shared queue (the heaviest first, so that the last to finish is a light one), and hands back
each job's result as bytes (the caller pickles its results: they pass only from a child
of this process, through a file nobody else can open, to it).

Processes are used only where ``fork`` exists and the parent runs a single thread — a child
forked beside other threads may inherit a lock one of them held and never return — and only
as many as the top of the run allows (:func:`allowed`): flake8 with ``-j1`` checks files in its
own process meanwhile, with ``--jobs`` its workers do. A job whose child died, or whose result
cannot be written as text, is left to the caller, which computes it in its own process: the
results never depend on the children.
"""
from __future__ import annotations

import contextlib
import os
import signal
import struct
import tempfile
import threading
from dataclasses import dataclass, field
from typing import Callable, Iterator, Sequence

#: Each queued job is its index as four bytes: reads of that size from a pipe are atomic, so
#: children taking jobs from one pipe never split one.
_JOB = struct.Struct("<I")
#: Each result is framed as (job index, length), then its bytes.
_FRAME = struct.Struct("<IQ")

#: Children at most, however many cores: each holds an analysis of its own beside its
#: copy-on-write view of the parent's memory.
MAX_PROCESSES = 8

#: Work (in the callers' unit: lines analysed) a single child must let the caller overlap with
#: its job to pay for the fork: about what analysing this many lines costs.
MIN_OVERLAP = 100

_allowed = 1


@contextlib.contextmanager
def processes(count: int) -> Iterator[None]:
    """Let the analysis use up to ``count`` processes inside the block (1: only its own). Set at
    the top of a run — the command line, or the child flake8 leaves the analysis to — which
    alone knows what else the machine's cores are doing."""
    global _allowed
    previous, _allowed = _allowed, max(1, count)
    try:
        yield
    finally:
        _allowed = previous


def allowed() -> int:
    """The processes the analysis may use now: 1 unless the run allowed more, ``fork`` exists
    and this process runs a single thread."""
    if _allowed < 2 or not hasattr(os, "fork") or threading.active_count() > 1:
        return 1
    return _allowed


def useful(weights: Sequence[int], meanwhile: int = 0) -> int:
    """How many children can shorten jobs of these ``weights`` (costs in any unit) while the
    caller does work of weight ``meanwhile`` itself; 0: none, the caller does the jobs after
    its own. Within :func:`allowed` and :data:`MAX_PROCESSES`, one per job at most, and no more
    than the total weight over the heaviest job's (that job bounds the run, however many
    processes help). A single child pays only when the caller has work of its own to overlap
    with it, worth more than a fork (:data:`MIN_OVERLAP`): a one-file edit's group analysed
    while the caller reads every other group's kept facts."""
    if not weights or allowed() < 2:
        return 0
    balance = -(-sum(weights) // max(max(weights), 1))
    count = min(allowed(), len(weights), balance, MAX_PROCESSES)
    if count >= 2:
        return count
    return 1 if min(meanwhile, sum(weights)) >= MIN_OVERLAP else 0


def cores() -> int:
    """The CPUs this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not on Linux
        return os.cpu_count() or 1


@dataclass
class _Child:
    pid: int
    #: Where the child writes its results: a temporary file, so that a child never waits for the
    #: parent to read (the parent may be busy with work of its own meanwhile).
    results: int


@dataclass
class ForkedJobs:
    """Jobs running in forked children; :meth:`collect` waits for them and returns the results."""

    children: list[_Child] = field(default_factory=list)

    @classmethod
    def start(cls, order: Sequence[int], work: Callable[[int], bytes | None], count: int) -> ForkedJobs:
        """Fork ``count`` children that run ``work(job)`` for the jobs of ``order``, in that order,
        each job once; ``work`` returns the job's result, or ``None`` for one to leave to the
        caller. The caller must have checked :func:`allowed`."""
        jobs = cls()
        try:
            read_end, write_end = os.pipe()
        except OSError:  # no descriptors left: every job is left to the caller
            return jobs
        try:
            for _ in range(count):
                child = _fork(read_end, write_end, work)
                if child is None:
                    break  # no more processes to be had: those forked share the queue
                jobs.children.append(child)
            os.close(read_end)
            read_end = -1
            if jobs.children:
                _queue(write_end, order)
        except BaseException:
            jobs.stop()
            raise
        finally:
            if read_end >= 0:
                os.close(read_end)
            os.close(write_end)  # the children see the end of the queue once it is empty
        return jobs

    def collect(self) -> dict[int, bytes]:
        """Wait for every child; the results they completed, by job."""
        found: dict[int, bytes] = {}
        try:
            for child in self.children:
                with contextlib.suppress(ChildProcessError):
                    os.waitpid(child.pid, 0)
                found.update(_frames(child.results))
        except BaseException:
            self.stop()
            raise
        finally:
            self._close()
        return found

    def stop(self) -> None:
        """End every child now (the parent was interrupted) and forget them."""
        for child in self.children:
            with contextlib.suppress(OSError):
                os.kill(child.pid, signal.SIGKILL)
            with contextlib.suppress(OSError):
                os.waitpid(child.pid, 0)
        self._close()

    def _close(self) -> None:
        for child in self.children:
            with contextlib.suppress(OSError):
                os.close(child.results)
        self.children = []


def _fork(queue: int, queue_writer: int, work: Callable[[int], bytes | None]) -> _Child | None:
    """A child taking jobs from ``queue``; ``None`` when no process can be had (a limit on
    processes or memory): what no child does is left to the caller."""
    try:
        with tempfile.TemporaryFile() as results:
            fd = os.dup(results.fileno())
    except OSError:
        return None
    try:
        pid = os.fork()
    except OSError:
        os.close(fd)
        return None
    if pid == 0:
        _child(queue, queue_writer, fd, work)  # never returns
    return _Child(pid, fd)


def _queue(fd: int, order: Sequence[int]) -> None:
    """Queue the jobs; once every child is gone (the pipe has no reader) the rest stays unqueued,
    left to the caller."""
    try:
        for job in order:
            os.write(fd, _JOB.pack(job))
    except BrokenPipeError:
        pass


def _child(queue: int, queue_writer: int, results: int, work: Callable[[int], bytes | None]) -> None:
    """A child's life: take jobs until the queue is empty, write each result, and exit without
    returning into the parent's code (nor running its exit handlers or flushing its buffers)."""
    status = 1
    try:
        os.close(queue_writer)
        while True:
            data = os.read(queue, _JOB.size)
            if len(data) < _JOB.size:
                break
            job = _JOB.unpack(data)[0]
            result = work(job)
            if result is not None:
                _write_all(results, _FRAME.pack(job, len(result)) + result)
        status = 0
    finally:
        os._exit(status)


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]


def _frames(fd: int) -> Iterator[tuple[int, bytes]]:
    """The complete results in a child's file (a child that died mid-write leaves a partial
    last one, which is dropped)."""
    os.lseek(fd, 0, os.SEEK_SET)
    with os.fdopen(os.dup(fd), "rb") as handle:
        data = handle.read()
    offset = 0
    while offset + _FRAME.size <= len(data):
        job, length = _FRAME.unpack_from(data, offset)
        start = offset + _FRAME.size
        if start + length > len(data):
            return
        yield job, data[start:start + length]
        offset = start + length
