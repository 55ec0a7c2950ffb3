"""What the benchmark scripts share: where the repository, the CLI and the shared models are,
the paper's Table 1 models, how a command is timed and its peak memory measured, and how a
benchmark's rows are written (OUT/NAME.json and OUT/NAME.csv)."""

import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections import namedtuple
from pathlib import Path

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(ROOT, "target", "release", "exact-geodesics")
MODELS = os.path.join(ROOT, "..", "shared", "models")
# The paper's Table 1 models, non-uniform and uniform, under MODELS.
PAPER_TABLE1 = [
    f"paper-table1/{shape}_{kind}"
    for shape in ("sphere", "eight", "teapot")
    for kind in ("uniform", "nonuniform")
]


def read_obj(path):
    """The vertices ``(x, y, z)`` and 0-based triangles of an OBJ file, in file order.

    Accepts ``v x y z [w]`` and ``f a b c`` lines with 1-based or negative
    (relative) indices, in the ``a``, ``a/t``, ``a//n`` and ``a/t/n`` forms;
    every other record and comments are ignored. Faces that are not triangles
    are an error (``ValueError`` naming the file and line)."""
    vertices = []
    triangles = []
    with open(path, encoding="utf-8") as lines:
        for lineno, line in enumerate(lines, start=1):
            fields = line.split("#", 1)[0].split()
            if not fields:
                continue
            if fields[0] == "v":
                vertices.append(tuple(float(x) for x in fields[1:4]))
            elif fields[0] == "f":
                corners = [int(token.split("/", 1)[0]) for token in fields[1:]]
                if len(corners) != 3:
                    raise ValueError(f"{path}:{lineno}: face with {len(corners)} vertices, expected 3")
                triangles.append(tuple(c - 1 if c > 0 else len(vertices) + c for c in corners))
    return vertices, triangles


def write_rows(out, name, rows):
    """Writes `rows` (a list of dicts) to OUT/NAME.json and OUT/NAME.csv (the union of their
    keys, in order of first appearance)."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump(rows, f, indent=2)
    fields = []
    for row in rows:
        fields += [k for k in row if k not in fields]
    with open(os.path.join(out, name + ".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)


class RunError(Exception):
    """One measured run failed; recorded for its model, the benchmark goes on."""


# One measured run: wall time, the child's user and system CPU seconds, its peak RSS.
Measured = namedtuple("Measured", "wall_seconds user_seconds system_seconds peak_rss_bytes")


def gnu_time():
    """The path of GNU time if it is installed (None otherwise): it reports the peak RSS of
    the command it runs, whose ``ru_maxrss`` then starts from GNU time's small one."""
    path = Path("/usr/bin/time")
    try:
        probe = subprocess.run([str(path), "--version"], capture_output=True, text=True)
    except OSError:
        return None
    return str(path) if "GNU" in probe.stdout + probe.stderr else None


GNU_TIME = gnu_time()
# How run_measured measures peak RSS, as recorded in the results.
RSS_METHOD = "gnu-time" if GNU_TIME else "wait4"


def run_measured(cmd, stdout_path, timeout):
    """Run ``cmd`` with stdout into ``stdout_path``; measure wall time and peak RSS.

    The peak RSS is GNU time's ``%M`` when it is installed (``RSS_METHOD``), else the
    child's ``ru_maxrss`` from ``os.wait4``, which includes this harness's high-water mark.
    The child runs in its own process group, killed whole on timeout or when
    the harness is interrupted. Returns a ``Measured``: its user and system CPU are the
    child's (with GNU time's own, a few milliseconds).
    Raises RunError when the command cannot start, exits non-zero or outlives
    ``timeout`` seconds.
    """
    timed_out = threading.Event()

    def kill_group(pid):
        try:
            os.killpg(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass

    def on_timeout(pid):
        timed_out.set()
        kill_group(pid)

    with open(stdout_path, "wb") as out, tempfile.TemporaryFile() as err, \
            tempfile.NamedTemporaryFile(mode="r", encoding="ascii") as rss:
        if GNU_TIME:
            cmd = [GNU_TIME, "-f", "%M", "-o", rss.name, *cmd]
        start = time.perf_counter()
        try:
            proc = subprocess.Popen(
                cmd, stdin=subprocess.DEVNULL, stdout=out, stderr=err, start_new_session=True
            )
        except OSError as exc:
            raise RunError(f"cannot start {cmd[0]}: {exc}") from exc
        timer = threading.Timer(timeout, on_timeout, args=(proc.pid,))
        timer.start()
        try:
            _, status, usage = os.wait4(proc.pid, 0)
        except BaseException:
            kill_group(proc.pid)
            proc.wait()
            raise
        finally:
            timer.cancel()
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        stderr = err.read().decode("utf-8", errors="replace").strip()
        reported = rss.read().strip()
    if timed_out.is_set():
        raise RunError(f"timed out after {timeout:g} s")
    if proc.returncode != 0:
        tail = "".join(f"\n    {line}" for line in stderr.splitlines()[-5:])
        raise RunError(f"exited with status {proc.returncode}{tail}")
    cpu = (usage.ru_utime, usage.ru_stime)
    if not GNU_TIME:
        peak = usage.ru_maxrss if sys.platform == "darwin" else usage.ru_maxrss * 1024
        return Measured(wall, *cpu, peak)
    if not reported.isdigit():
        raise RunError(f"GNU time reported no peak RSS: {reported!r}")
    return Measured(wall, *cpu, int(reported) * 1024)
