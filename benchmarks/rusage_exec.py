"""Run one command and write its wall time, CPU time and peak memory to a file.

``python -S rusage_exec.py OUT -- COMMAND...`` forks, executes COMMAND, waits for
it with ``os.wait4`` and writes ``wall_s cpu_s maxrss`` (``ru_maxrss``: KiB on
Linux, bytes on macOS) to OUT; its exit status is COMMAND's.

Why a separate small process: Linux counts the memory a process had *before*
``exec`` in its peak (``ru_maxrss`` survives exec). A command started directly by
the benchmark would inherit the benchmark's own size as its floor; started from
this ~8 MB launcher (no ``site``, nothing imported but ``os``/``sys``/``time``),
the floor is below any Python command's own footprint, so the peak is the
command's. The wall time is taken here, around fork and wait, so the launcher's
own start-up is not counted either. Unix only.
"""
import os
import sys
import time


def main(argv: list) -> int:
    out_path, separator, command = argv[0], argv[1], argv[2:]
    if separator != "--" or not command:
        print("usage: rusage_exec.py OUT -- COMMAND...", file=sys.stderr)
        return 2
    start = time.perf_counter()
    pid = os.fork()
    if pid == 0:
        try:
            os.execvp(command[0], command)
        finally:
            os._exit(127)
    _, status, usage = os.wait4(pid, 0)
    wall = time.perf_counter() - start
    with open(out_path, "w", encoding="ascii") as out:
        out.write(f"{wall!r} {usage.ru_utime + usage.ru_stime!r} {usage.ru_maxrss}\n")
    return os.waitstatus_to_exitcode(status)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
