"""The debug APK's dex, as AGP builds it for a debuggable variant: each library jar dexed alone by D8 in
intermediate mode (AGP's dexing transform), cached by the jar's content in a cache the clones of this machine share,
so that a jar is dexed once per machine, then the jars' dex merged by D8 once per set of libraries (AGP's
mergeExtDex); each of the app's own modules dexed alone and cached by content, so that an edit re-dexes only its
module. tools/offline-build/java/LibraryDexer.java does the dexing (and the merge) in one JVM and reports each jar as
it ends, from which the build prints its progress and estimate.
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
import zipfile
from dataclasses import dataclass

from .errors import BuildError
from .ui import info, progress

# Before any run on this machine has been timed: D8 wall time per MB of library jar, and of the merge, on two
# idle cores, from the CPU time of the project's 101 jars (44.9 MB) measured under load on 2026-11-28: 364 s of
# CPU for the jars (docs/build.md), the merge about a minute.
DEFAULT_DEX_MS_PER_MB = 4000.0
DEFAULT_MERGE_MS_PER_MB = 1000.0
# The app's modules are dexed from uncompressed class files (module_jar), so per MB D8 has less to do than for a
# compressed library jar.
DEFAULT_MODULE_MS_PER_MB = 1500.0
PROGRESS_EVERY_S = 5.0
# What a merged set's directory holds, part of its key: intermediate dex (classes*.dex) and globals/*.zip.
MERGED_LAYOUT = "intermediate+globals"
MODE = "debug"  # D8's compilation mode, part of each cache key: LibraryDexer compiles in debug mode


@dataclass(frozen=True)
class D8Tool:
    """What LibraryDexer runs with: the JVM, its classpath (the compiled helper and R8's jar), the library jars D8
    resolves against, minSdk, the project's build cache, how many jars to dex at a time, and the dex cache the
    clones of this machine share ([shared_dex_cache]; without one, the libraries' dex stays in `cache`)."""
    java: str
    classpath: list[str]
    r8_jar: str
    android_jar: str
    java_home: str
    min_sdk: str
    cache: str
    threads: int
    shared: str = ""

    @property
    def jars_root(self) -> str:
        """Each library jar's dex, by [jar_key]."""
        return os.path.join(self.shared, "jars") if self.shared else os.path.join(self.cache, "dex", "jars")

    @property
    def libraries_root(self) -> str:
        """Each merged set of libraries, by the key of the set."""
        return os.path.join(self.shared, "libraries") if self.shared else os.path.join(self.cache, "dex", "libraries")


def shared_dex_cache(env=os.environ, home: str = os.path.expanduser("~")) -> str:
    """Where the libraries' dex is kept (each jar's, and each merged set's), shared by every clone of the project on
    this machine, as Gradle keeps AGP's dexed jars in its user home (`~/.gradle/caches/…/transforms`):
    `HAPTICON_DEX_CACHE`, else `$XDG_CACHE_HOME/hapticon/dex`, else `~/.cache/hapticon/dex`. A jar's dex depends only
    on the jar's content, the D8 version, minSdk and the mode ([jar_key]), a merged set only on its jars' keys, so
    sharing them is safe."""
    if env.get("HAPTICON_DEX_CACHE"):
        return env["HAPTICON_DEX_CACHE"]
    return os.path.join(env.get("XDG_CACHE_HOME") or os.path.join(home, ".cache"), "hapticon", "dex")


# A merged set of libraries unused this long is deleted from the shared cache (several clones may use several sets).
SHARED_SET_DAYS = 7


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
    return keys, os.path.join(tool.libraries_root, set_key)


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
    """The merged dex files of `jars` (classpath order). Each jar's dex is kept in `<jars_root>/<jar key>/` and the
    merged set in `<libraries_root>/<set key>/` ([D8Tool]); only what is missing is made, and a run of the same set
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
        os.utime(merged)  # in use: kept in the shared cache ([SHARED_SET_DAYS])
        info(f"library dex up to date ({len(jars)} jars, {merged})")
        return dex_files(merged)
    loud = threading.Event()
    loud.set()
    _make(jars, tool, loud)
    return dex_files(merged)


def _make(jars: list[str], tool: D8Tool, loud: threading.Event) -> None:
    """Dexes the jars not cached yet and merges the set; prints progress while `loud` is set."""
    keys, merged = _locate(jars, tool)
    jar_root = tool.jars_root
    merged_root = os.path.dirname(merged)
    os.makedirs(jar_root, exist_ok=True)
    os.makedirs(merged_root, exist_ok=True)
    tag = f".tmp{os.getpid()}"
    jobs, pending = _jobs(jars, [os.path.join(jar_root, key) for key in keys])
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
    run = _run_dexer(tool, jobs, pending, sizes, out, say, "jars", timing["dex_ms_per_mb"], merge_estimate, jars)
    if run.failed or run.merge_ms is None:
        shutil.rmtree(out, ignore_errors=True)
        raise BuildError(f"D8 of the library jars failed (exit {run.returncode})\n{run.tail}")
    for old in os.listdir(merged_root):
        # One clone, one app: only the current set of libraries is worth keeping merged. In the shared cache other
        # clones' sets stay until unused for [SHARED_SET_DAYS] days.
        path = os.path.join(merged_root, old)
        unused = time.time() - os.path.getmtime(path) > SHARED_SET_DAYS * 86400 if tool.shared else True
        if old != os.path.basename(out) and ".tmp" not in old and unused:
            shutil.rmtree(path, ignore_errors=True)
    # The jars' global synthetics, beside their merged dex: compiled once with the app's (AndroidApp._dex).
    os.makedirs(os.path.join(out, "globals"))
    for i, (_jar, directory) in enumerate(jobs):
        if os.path.exists(os.path.join(directory, "globals.zip")):
            shutil.copyfile(os.path.join(directory, "globals.zip"), os.path.join(out, "globals", f"{i}.zip"))
    try:
        os.rename(out, merged)
    except OSError:  # another clone merged the same set first
        shutil.rmtree(out, ignore_errors=True)
    dexed_mb = sum(sizes.values())
    _write_timing(tool.cache, {
        "dex_ms_per_mb": run.dex_s * 1000 / dexed_mb if dexed_mb > 5 else timing["dex_ms_per_mb"],
        "merge_ms_per_mb": run.merge_ms / total_mb if total_mb > 0 else timing["merge_ms_per_mb"]})
    say(f"D8: {len(pending)} jars dexed in {run.dex_s:.1f} s, merged in {run.merge_ms / 1000:.1f} s")


def dex_modules(jars: list[str], tool: D8Tool) -> list[str]:
    """The dex directories of the app's own modules, one jar each ([module_jar]), in order: each dexed alone by D8
    (intermediate, debug mode, global synthetics apart), as AGP dexes a debuggable variant's project classes, and
    kept by content in `cache/dex/modules/<jar key>/`, so that a change re-dexes only the module it touches. Not
    merged: minSdk ≥ 21 loads every classesN.dex of the APK natively. Only the current modules' dex is kept."""
    root = os.path.join(tool.cache, "dex", "modules")
    os.makedirs(root, exist_ok=True)
    keys = [jar_key(j, tool) for j in jars]
    finals = [os.path.join(root, k) for k in keys]
    jobs, pending = _jobs(jars, finals)
    names = ", ".join(os.path.basename(jars[i]).removesuffix(".jar") for i in pending)
    if pending:
        timing = _read_timing(tool.cache)
        sizes = {i: os.path.getsize(jars[i]) / 1e6 for i in pending}
        info(f"D8 of the app's modules: {len(pending)} of {len(jars)} to dex ({names}; {sum(sizes.values()):.1f} MB, "
             f"{len(jars) - len(pending)} unchanged); ~{sum(sizes.values()) * timing['module_ms_per_mb'] / 1000:.0f} s")
        run = _run_dexer(tool, jobs, pending, sizes, None, info, "modules", timing["module_ms_per_mb"], 0.0, jars)
        if run.failed:
            raise BuildError(f"D8 of the app's modules failed (exit {run.returncode})\n{run.tail}")
        dexed_mb = sum(sizes.values())
        if dexed_mb > 1:
            _write_timing(tool.cache, {"module_ms_per_mb": run.dex_s * 1000 / dexed_mb})
        info(f"D8 of the app's modules: {len(pending)} dexed in {run.dex_s:.1f} s")
    else:
        info(f"D8 of the app's modules: all {len(jars)} unchanged")
    for old in os.listdir(root):  # an edited module's old dex is never used again
        if old not in keys and ".tmp" not in old:
            shutil.rmtree(os.path.join(root, old), ignore_errors=True)
    return finals


def _jobs(jars: list[str], finals: list[str]) -> tuple[list[tuple[str, str]], dict[int, str]]:
    """LibraryDexer's jobs, `(jar, its dex directory)` or `("-", directory)` for one dexed already, and the
    directories still to make by job index."""
    jobs, pending = [], {}
    for i, (jar, final) in enumerate(zip(jars, finals)):
        if os.path.isdir(final):
            jobs.append(("-", final))
        else:
            jobs.append((jar, final))
            pending[i] = final
    return jobs, pending


@dataclass
class _DexerRun:
    returncode: int
    done: set
    merge_ms: int | None
    dex_s: float
    tail: str
    expected: int

    @property
    def failed(self) -> bool:
        return self.returncode != 0 or len(self.done) < self.expected


def write_jobs(tool: D8Tool, jobs: list[tuple[str, str]]) -> str:
    """Writes LibraryDexer's job list (`jar<TAB>out dir` lines) into the project's build cache and returns its path.
    The directory is made here: with the dex in a shared cache elsewhere, a fresh clone has no `.build-cache/dex/`."""
    directory = os.path.join(tool.cache, "dex")
    os.makedirs(directory, exist_ok=True)
    jobs_file = os.path.join(directory, f"jobs.tmp{os.getpid()}.{threading.get_ident()}")
    with open(jobs_file, "w") as f:
        f.writelines(f"{jar}\t{out}\n" for jar, out in jobs)
    return jobs_file


def _run_dexer(tool: D8Tool, jobs: list[tuple[str, str]], pending: dict[int, str], sizes: dict[int, float],
               merge_out: str | None, say, unit: str, ms_per_mb: float, merge_estimate: float,
               jars: list[str]) -> _DexerRun:
    """Runs LibraryDexer on `jobs` (`(jar, out dir)`, `-` for one cached), prints progress through `say` every
    [PROGRESS_EVERY_S] with an estimate (this run's own rate once a few MB are done, else `ms_per_mb`). LibraryDexer
    puts each jar's dex in its place as soon as it is done, so a failure or a stopped build keeps what was done."""
    jobs_file = write_jobs(tool, jobs)
    cmd = [tool.java, "-Xmx2g", "-XX:+UseParallelGC", "-cp", os.pathsep.join(tool.classpath), "LibraryDexer",
           tool.min_sdk, tool.android_jar, tool.java_home, str(tool.threads), jobs_file, merge_out or "-"]
    log_lines, done, merge_ms = [], set(), None
    started = time.monotonic()
    merge_started = None if pending else started
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
        if now - last_print >= PROGRESS_EVERY_S:
            last_print = now
            if merge_started is None:
                done_mb = sum(sizes[i] for i in done)
                if done_mb > 1:  # this run's own rate
                    left = (sum(sizes.values()) - done_mb) * (now - started) / done_mb + merge_estimate
                    say(f"D8: {len(done)}/{len(pending)} {unit}, ~{left:.0f} s left")
                else:
                    expected = sum(sizes.values()) * ms_per_mb / 1000 + merge_estimate
                    say(f"D8: {len(done)}/{len(pending)} {unit}, {progress(now - started, expected)}")
            elif merge_out and merge_ms is None:
                left = merge_estimate - (now - merge_started)
                say(f"D8 merge of {len(jobs)} jars' dex: {now - merge_started:.0f} s, "
                    + (f"~{left:.0f} s left" if left >= 1 else f"longer than the ~{merge_estimate:.0f} s expected"))
    proc.wait()
    os.remove(jobs_file)
    with open(os.path.join(tool.cache, "dex", f"{unit}.log"), "w") as f:  # D8's time per jar: "DONE <job> <ms>"
        f.writelines(f"{line.rstrip()}\t{jobs[int(line.split()[1])][0]}\n" if line.startswith("DONE") else line
                     for line in log_lines)
    # D8's own messages (e.g. "Type a.B is defined multiple times: …") and each failed jar by its path.
    shown = [re.sub(r"^FAIL (\d+)", lambda m: f"FAIL {jars[int(m.group(1))]}:", line.rstrip())
             for line in log_lines if not line.startswith(("DONE", "\tat "))]
    return _DexerRun(proc.returncode, done, merge_ms, (merge_started or time.monotonic()) - started,
                     "\n".join(shown[-30:]), len(pending))


def module_jar(entry: str, jar: str) -> bool:
    """Writes the class files of `entry` (a class directory or a jar) into `jar`, stored, sorted and with fixed
    times, so that its content key ([jar_key]) changes only when a class does; False (and no jar) if it has none."""
    from .android import _iter_files
    # Read while iterating: a jar's entries can be read only while _iter_files holds it open.
    classes = sorted((n, read()) for n, read in _iter_files(entry)
                     if n.endswith(".class") and not n.startswith("META-INF/"))
    if not classes:
        return False
    with zipfile.ZipFile(jar + ".tmp", "w", zipfile.ZIP_STORED) as z:
        for name, data in classes:
            z.writestr(zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0)), data)
    os.replace(jar + ".tmp", jar)
    return True


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
    timing = {"dex_ms_per_mb": DEFAULT_DEX_MS_PER_MB, "merge_ms_per_mb": DEFAULT_MERGE_MS_PER_MB,
              "module_ms_per_mb": DEFAULT_MODULE_MS_PER_MB}
    try:
        with open(_timing_path(cache)) as f:
            timing.update({k: float(v) for k, v in json.load(f).items() if k in timing})
    except (OSError, ValueError):
        pass
    return timing


def _write_timing(cache: str, rates: dict[str, float]) -> None:
    """Updates `rates` in `cache/dex/timing.json`, keeping the others (the library and module dex may end together)."""
    with _timing_lock:
        timing = _read_timing(cache)
        timing.update(rates)
        with open(_timing_path(cache) + ".tmp", "w") as f:
            json.dump(timing, f)
        os.replace(_timing_path(cache) + ".tmp", _timing_path(cache))


_timing_lock = threading.Lock()
