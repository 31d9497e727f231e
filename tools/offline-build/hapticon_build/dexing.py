"""The debug APK's library dex, as AGP builds it for a debuggable variant: each library jar dexed alone by D8 in
intermediate mode (AGP's dexing transform), cached by the jar's content so that a jar is dexed once ever, then the
jars' dex merged by D8 once per set of libraries (AGP's mergeExtDex). tools/offline-build/java/LibraryDexer.java
does both in one JVM and reports each jar as it ends, from which the build prints its progress and estimate.
"""
from __future__ import annotations

import hashlib
import json
import os
import queue
import re
import shutil
import subprocess
import threading
import time
from dataclasses import dataclass

from .errors import BuildError
from .ui import info

# Before any run on this machine has been timed: D8 wall time per MB of library jar, and of the merge, on two
# idle cores, from the CPU time of the project's 101 jars (44.9 MB) measured under load on 2026-11-28: 364 s of
# CPU for the jars (docs/build.md), the merge about a minute.
DEFAULT_DEX_MS_PER_MB = 4000.0
DEFAULT_MERGE_MS_PER_MB = 1000.0
PROGRESS_EVERY_S = 5.0
# What a merged set's directory holds, part of its key: intermediate dex (classes*.dex) and globals/*.zip.
MERGED_LAYOUT = "intermediate+globals"
MODE = "debug"  # D8's compilation mode, part of each cache key: LibraryDexer compiles in debug mode


@dataclass(frozen=True)
class D8Tool:
    """What LibraryDexer runs with: the JVM, its classpath (the compiled helper and R8's jar), the library jars D8
    resolves against, minSdk, the build cache and how many jars to dex at a time."""
    java: str
    classpath: list[str]
    r8_jar: str
    android_jar: str
    java_home: str
    min_sdk: str
    cache: str
    threads: int


def jar_key(jar: str, tool: D8Tool) -> str:
    """A jar's dex cache key: its content, the D8 (R8 jar name), minSdk and the mode; not its path, so a jar
    copied or re-downloaded elsewhere is not dexed again."""
    h = hashlib.sha1()
    with open(jar, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    h.update(f"\0{os.path.basename(tool.r8_jar)}\0{tool.min_sdk}\0{MODE}".encode())
    return h.hexdigest()[:20]


def dex_files(directory: str) -> list[str]:
    """classes.dex, classes2.dex, … of a D8 output directory, in that order."""
    found = [f for f in os.listdir(directory) if re.fullmatch(r"classes\d*\.dex", f)]
    return [os.path.join(directory, f) for f in sorted(found, key=lambda f: int(f[7:-4] or 1))]


def _locate(jars: list[str], tool: D8Tool) -> tuple[list[str], str]:
    """The jars' cache keys and the directory of their merged dex."""
    keys = [jar_key(j, tool) for j in jars]
    set_key = hashlib.sha1("\n".join(keys + [MERGED_LAYOUT]).encode()).hexdigest()[:20]
    return keys, os.path.join(tool.cache, "dex", "libraries", set_key)


# Runs started by [start_in_background], by their merged directory: (thread, "print progress" flag, failure if any).
_background: dict[str, tuple[threading.Thread, threading.Event, list]] = {}


def start_in_background(jars: list[str], tool: D8Tool) -> None:
    """Starts [dex_libraries] on a thread, silent, unless the set is merged already: a build runs it beside work
    that leaves a core idle (Kotlin compiles one file set at a time, a test JVM mostly runs one test at a time), and
    the APK's [dex_libraries] or [finish_background] waits for it, then printing its progress."""
    _keys, merged = _locate(jars, tool)
    if os.path.isdir(merged) or merged in _background:
        return
    loud, failure = threading.Event(), []

    def work():
        try:
            _make(jars, tool, loud)
        except (BuildError, OSError) as e:
            failure.append(e)
    thread = threading.Thread(target=work, name="library dex")
    thread.start()
    _background[merged] = (thread, loud, failure)
    info(f"D8 of the app's {len(jars)} library jars (for the APK) runs in the background")


def finish_background() -> None:
    """Waits for the runs [start_in_background] started, showing their progress; a failure is only reported
    here (the APK's build tries again and fails with it)."""
    for merged, (thread, loud, failure) in list(_background.items()):
        if thread.is_alive():
            info("waiting for the library dex started in the background (the APK's)")
            loud.set()
            thread.join()
        if failure:
            info(f"the library dex started in the background failed; ./build apk will say why")
        del _background[merged]


def dex_libraries(jars: list[str], tool: D8Tool) -> list[str]:
    """The merged dex files of `jars` (classpath order). Each jar's dex is kept in `cache/dex/jars/<jar key>/` and
    the merged set in `cache/dex/libraries/<set key>/`; only what is missing is made, and a run of the same set
    started in the background is waited for."""
    _keys, merged = _locate(jars, tool)
    if merged in _background:
        thread, loud, failure = _background.pop(merged)
        if thread.is_alive():
            info("waiting for the library dex started in the background")
            loud.set()
            thread.join()
        if failure:
            raise failure[0]
    if os.path.isdir(merged):
        info(f"library dex up to date ({len(jars)} jars, {os.path.relpath(merged, os.path.dirname(tool.cache))})")
        return dex_files(merged)
    loud = threading.Event()
    loud.set()
    _make(jars, tool, loud)
    return dex_files(merged)


def _make(jars: list[str], tool: D8Tool, loud: threading.Event) -> None:
    """Dexes the jars not cached yet and merges the set; prints progress while `loud` is set."""
    keys, merged = _locate(jars, tool)
    jar_root = os.path.join(tool.cache, "dex", "jars")
    merged_root = os.path.dirname(merged)
    os.makedirs(jar_root, exist_ok=True)
    os.makedirs(merged_root, exist_ok=True)
    tag = f".tmp{os.getpid()}"
    jobs, pending = [], {}
    for i, (jar, key) in enumerate(zip(jars, keys)):
        final = os.path.join(jar_root, key)
        if os.path.isdir(final):
            jobs.append(("-", final))
        else:
            shutil.rmtree(final + tag, ignore_errors=True)
            jobs.append((jar, final + tag))
            pending[i] = final
    jobs_file = os.path.join(merged_root, "jobs" + tag)
    with open(jobs_file, "w") as f:
        f.writelines(f"{jar}\t{out}\n" for jar, out in jobs)
    timing = _read_timing(tool.cache)
    sizes = {i: os.path.getsize(jars[i]) / 1e6 for i in pending}
    total_mb = sum(os.path.getsize(j) for j in jars) / 1e6
    merge_estimate = total_mb * timing["merge_ms_per_mb"] / 1000

    def say(message: str) -> None:
        if loud.is_set():
            info(message)
    say(f"D8: {len(pending)} of {len(jars)} library jars to dex ({sum(sizes.values()):.1f} MB, "
         f"{len(jars) - len(pending)} cached), then their merge; "
         f"~{sum(sizes.values()) * timing['dex_ms_per_mb'] / 1000 + merge_estimate:.0f} s")
    out = merged + tag
    shutil.rmtree(out, ignore_errors=True)
    cmd = [tool.java, "-Xmx2g", "-XX:+UseParallelGC", "-cp", os.pathsep.join(tool.classpath), "LibraryDexer",
           tool.min_sdk, tool.android_jar, tool.java_home, str(tool.threads), jobs_file, out]
    log_lines, done, merge_ms = [], set(), None
    started = time.monotonic()
    merge_started = None
    last_print = started
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    lines: queue.Queue = queue.Queue()
    threading.Thread(target=_forward, args=(proc.stdout, lines), daemon=True).start()
    while True:
        try:
            line = lines.get(timeout=1.0)
        except queue.Empty:
            line = ""
        if line is None:
            break
        now = time.monotonic()
        if line:
            log_lines.append(line)
            if m := re.match(r"DONE (\d+) \d+", line):
                done.add(int(m.group(1)))
                if len(done) == len(pending):
                    merge_started = now
            elif m := re.match(r"MERGED (\d+)", line):
                merge_ms = int(m.group(1))
        if not pending and merge_started is None:
            merge_started = started
        if now - last_print >= PROGRESS_EVERY_S:
            last_print = now
            if merge_started is None:
                done_mb = sum(sizes[i] for i in done)
                rate = (now - started) / done_mb if done_mb > 1 else timing["dex_ms_per_mb"] / 1000
                left = (sum(sizes.values()) - done_mb) * rate + merge_estimate
                say(f"D8: {len(done)}/{len(pending)} jars, ~{left:.0f} s left")
            elif merge_ms is None:
                left = merge_estimate - (now - merge_started)
                say(f"D8 merge of {len(jars)} jars' dex: {now - merge_started:.0f} s, "
                    + (f"~{left:.0f} s left" if left >= 1 else f"longer than the ~{merge_estimate:.0f} s expected"))
    proc.wait()
    os.remove(jobs_file)
    for i in done:  # a jar dexed is kept even if another failed or the merge did
        shutil.rmtree(pending[i], ignore_errors=True)
        os.replace(pending[i] + tag, pending[i])
    for i in set(pending) - done:
        shutil.rmtree(pending[i] + tag, ignore_errors=True)
    if proc.returncode != 0 or merge_ms is None:
        shutil.rmtree(out, ignore_errors=True)
        # D8's own messages (e.g. "Type a.B is defined multiple times: …") and each failed jar by its path.
        lines = [re.sub(r"^FAIL (\d+)", lambda m: f"FAIL {jars[int(m.group(1))]}:", l.rstrip())
                 for l in log_lines if not l.startswith(("DONE", "\tat "))]
        tail = "\n".join(lines[-30:])
        raise BuildError(f"D8 of the library jars failed (exit {proc.returncode})\n{tail}")
    for old in os.listdir(merged_root):  # one app: only the current set of libraries is worth keeping merged
        if not old.startswith(("jobs", "timing")) and old != os.path.basename(out):
            shutil.rmtree(os.path.join(merged_root, old), ignore_errors=True)
    # The jars' global synthetics, beside their merged dex: compiled once with the app's (AndroidApp._dex).
    os.makedirs(os.path.join(out, "globals"))
    for i, (_jar, directory) in enumerate(jobs):
        directory = pending.get(i, directory)
        if os.path.exists(os.path.join(directory, "globals.zip")):
            shutil.copyfile(os.path.join(directory, "globals.zip"), os.path.join(out, "globals", f"{i}.zip"))
    os.replace(out, merged)
    dex_s = (merge_started or time.monotonic()) - started
    dexed_mb = sum(sizes.values())
    _write_timing(tool.cache, {
        "dex_ms_per_mb": dex_s * 1000 / dexed_mb if dexed_mb > 5 else timing["dex_ms_per_mb"],
        "merge_ms_per_mb": merge_ms / total_mb if total_mb > 0 else timing["merge_ms_per_mb"]})
    say(f"D8: {len(pending)} jars dexed in {dex_s:.1f} s, merged in {merge_ms / 1000:.1f} s")


def library_globals(dexes: list[str]) -> list[str]:
    """The global synthetics files kept beside the merged library dex that [dex_libraries] returned."""
    folder = os.path.join(os.path.dirname(dexes[0]), "globals") if dexes else ""
    return sorted(os.path.join(folder, f) for f in os.listdir(folder)) if os.path.isdir(folder) else []


def _forward(stream, lines: queue.Queue) -> None:
    """Puts each line of `stream` on `lines`, then None: the build reads them with a timeout, to print progress
    while D8 is silent (a large jar, the merge)."""
    for line in stream:
        lines.put(line)
    lines.put(None)


def _timing_path(cache: str) -> str:
    return os.path.join(cache, "dex", "timing.json")


def _read_timing(cache: str) -> dict[str, float]:
    """The last run's rates on this machine (`cache/dex/timing.json`), else [DEFAULT_DEX_MS_PER_MB]'s."""
    timing = {"dex_ms_per_mb": DEFAULT_DEX_MS_PER_MB, "merge_ms_per_mb": DEFAULT_MERGE_MS_PER_MB}
    try:
        with open(_timing_path(cache)) as f:
            timing.update({k: float(v) for k, v in json.load(f).items() if k in timing})
    except (OSError, ValueError):
        pass
    return timing


def _write_timing(cache: str, timing: dict[str, float]) -> None:
    with open(_timing_path(cache), "w") as f:
        json.dump(timing, f)
