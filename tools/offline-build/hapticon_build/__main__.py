"""./build COMMAND — the offline build. Run `./build help` for the commands."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import threading
import time

from . import ui
from .builder import MAIN_RUNTIME, Build, TestResult
from .errors import BuildError
from .project import load_project

USAGE = """usage: ./build COMMAND [options]
  apk                 build and verify the signed debug APK (out/app/hapticon-debug.apk)
  apk --release [--keystore PATH --key-alias ALIAS]
                      R8-shrunk release APK (out/app/hapticon-release.apk), signed with a release
                      key (passwords from HAPTICON_RELEASE_STORE_PASSWORD / _KEY_PASSWORD; see
                      docs/release.md), verified, and its R8 output smoke-checked
  test [MODULE...] [--tests REGEX]
                      compile and run tests (all modules by default); the last line is
                      "N passed, N failed, N skipped"; exits 1 on any failure
  screenshots [--tests REGEX]
                      run the app's screenshot tests recording docs/images/screens/*.png
                      (`./build test :app` compares against them instead)
  device-check [--tests CLASS[#METHOD]]
                      build the debug APK and the device check's test APK (device-check/); with a
                      phone attached over adb, run the instrumented suite against a broker started
                      here (docs/device-check.md); without one, say so and exit 0
  companion           build the companion command-line tool (used by ./hapticon)
  demo                build the APK, then run the companion demo into out/demo
  bench               build the companion and run `hapticon bench`
  bench --arrival [N] the app's arrival-to-touch benchmark over N messages (default 10,000; Robolectric,
                      embedded broker): p50/p99/max per stage beside decoding alone (docs/performance.md)
  classpath MODULE [main|test]
                      print a module's runtime classpath
  clean               delete out/ (keeps downloaded artifacts and .build-cache/)
options: --quiet (no progress), --offline (use only the local Maven repository)"""


def main(argv: list[str]) -> int:
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
    args = [a for a in argv if a not in ("--quiet", "--offline")]
    ui.QUIET = "--quiet" in argv
    if "--offline" in argv:
        os.environ["HAPTICON_OFFLINE"] = "1"
    if not args or args[0] in ("help", "-h", "--help"):
        print(USAGE)
        return 0 if args else 2
    command, rest = args[0], args[1:]
    started = time.monotonic()
    try:
        project = load_project(root)
        build = Build(project)
        if command == "test":
            return run_tests(build, rest)
        if command == "screenshots":
            return record_screenshots(build, rest)
        if command == "device-check":
            from .device_check import main as device_check
            return device_check(build, rest)
        if command == "apk":
            from .android import AndroidApp, Signing
            app = AndroidApp(build, app_module(project))
            if "--release" in rest:
                signing = Signing.from_args(rest)  # before any work: a missing key fails at once
                apk = app.assemble_release(signing)
            else:
                apk = app.assemble()
            print(apk)
        elif command == "companion":
            companion_classpath(build)
        elif command == "classpath":
            m = project.module(rest[0])
            print(os.pathsep.join(build.runtime_classpath(m, rest[1] if len(rest) > 1 else "main")))
        elif command == "demo":
            run_demo(build)
        elif command == "bench" and "--arrival" in rest:
            return bench_arrival(build, arrival_count(rest))
        elif command == "bench":
            cp = companion_classpath(build)
            build.kotlinc.close()
            run_companion(build, cp, ["bench"] + rest)
        elif command == "clean":
            shutil.rmtree(os.path.join(root, "out"), ignore_errors=True)
        else:
            print(USAGE, file=sys.stderr)
            return 2
    except BuildError as e:
        print(f"build failed: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    finally:
        from .dexing import finish_background
        finish_background()  # a library dex started in the background ends (and is kept) before the build does
    ui.info(f"{command} done in {time.monotonic() - started:.1f} s")
    return 0


def app_module(project):
    apps = [m for m in project.modules.values() if m.is_android_app]
    if not apps:
        raise BuildError("no module applies the android-application plugin")
    return apps[0]


def companion_classpath(build: Build) -> list[str]:
    module = build.project.module(":companion")
    cp = build.runtime_classpath(module, "main")
    path = os.path.join(build.out, "companion", "runtime-classpath.txt")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(os.pathsep.join(cp) + "\n")
        f.write((module.main_class or "") + "\n")
    with open(os.path.join(build.out, "companion", "inputs.txt"), "w") as f:
        f.write("".join(p + "\n" for p in companion_inputs(build.project)))
    return cp


def companion_inputs(project) -> list[str]:
    """
    Every file or directory whose change can change the companion, relative to the project root: the
    main sources and build file of the companion and of each module it runs with, the convention plugins
    those build files apply, the settings, the version catalog and this build tool. ./hapticon fingerprints these (paths, sizes, mtimes) in bash
    and calls the build only when the fingerprint differs from the one of its last successful build.
    """
    modules, stack = [], [project.module(":companion")]
    while stack:
        m = stack.pop()
        if m in modules:
            continue
        modules.append(m)
        stack += project.project_deps(m, *MAIN_RUNTIME)
    inputs = ["settings.gradle.kts", os.path.join("gradle", "libs.versions.toml"),
              os.path.join("tools", "offline-build", "hapticon_build"), os.path.join("tools", "offline-build", "java")]
    for m in sorted(modules, key=lambda m: m.path):
        rel = os.path.relpath(m.directory, project.root)
        inputs += [os.path.join(rel, "build.gradle.kts"), os.path.join(rel, "src", "main")]
    # The convention plugins those build files apply declare plugins and dependencies too.
    conventions = {os.path.relpath(c, project.root) for m in modules for c in m.conventions}
    return inputs + sorted(conventions)


def run_companion(build: Build, classpath: list[str], args: list[str]) -> None:
    module = build.project.module(":companion")
    cmd = [build.tools.java, "-Djava.awt.headless=true", "-cp", os.pathsep.join(classpath), module.main_class] + args
    code = subprocess.call(cmd, cwd=build.root)
    if code != 0:
        raise BuildError(f"hapticon {' '.join(args)} exited {code}")


# Before the companion's demo has been timed on this machine, its estimate in seconds (docs/build.md).
DEMO_S = 30.0


def run_demo(build: Build) -> None:
    """`./build demo`: the debug APK and the companion's demo. The demo needs no APK, so it runs as soon as the
    companion is compiled, beside the rest of the APK's build (the app's own Kotlin, its dex, packaging), which
    leaves a core idle most of the time; its output is printed when it ends, then the APK's line. The library dex
    starts first of all, in the background ([AndroidApp.start_library_dex])."""
    from .android import AndroidApp
    app = AndroidApp(build, app_module(build.project))
    app.start_library_dex()
    cp = companion_classpath(build)
    module = build.project.module(":companion")
    log_path = os.path.join(build.out, "demo.log")
    os.makedirs(build.out, exist_ok=True)
    with open(log_path, "w") as log:
        ui.info("the companion's demo runs beside the APK's build (out/demo.log)")
        started = time.monotonic()
        demo = subprocess.Popen([build.tools.java, "-Djava.awt.headless=true", "-cp", os.pathsep.join(cp),
                                 module.main_class, "demo", "--out", os.path.join(build.root, "out", "demo")],
                                cwd=build.root, stdout=log, stderr=subprocess.STDOUT)
        ended = []
        waiter = threading.Thread(target=lambda: ended.append((demo.wait(), time.monotonic())), daemon=True)
        waiter.start()
        try:
            apk = app.assemble()
            build.kotlinc.close()
        finally:
            if waiter.is_alive():
                expected = build.stage_times.expected("companion demo", DEMO_S) - (time.monotonic() - started)
                with ui.Stage("waiting for the companion's demo", max(expected, 1.0)):
                    waiter.join()
            waiter.join()
    code, end = ended[0]
    if code == 0:
        build.stage_times.record("companion demo", end - started)
    sys.stdout.write(open(log_path).read())
    if code != 0:
        raise BuildError(f"hapticon demo exited {code} (out/demo.log)")
    size = os.path.getsize(apk)
    print(f"APK: {apk} ({size} bytes, {size / 1e6:.1f} MB)")


def run_tests(build: Build, rest: list[str]) -> int:
    name_filter = None
    if "--tests" in rest:
        i = rest.index("--tests")
        name_filter = rest[i + 1]
        rest = rest[:i] + rest[i + 2:]
    modules = [build.project.module(m) for m in rest] if rest else build.project.in_dependency_order()
    results = []
    if not rest:
        # Every test: then the APK comes next (the README's `./build demo`), and its library dex, minutes of D8
        # once per set of libraries, runs beside the tests, which mostly leave a core idle.
        from .android import AndroidApp
        AndroidApp(build, app_module(build.project)).start_library_dex()
    try:
        if not rest:
            results.append(build_tool_tests(build.root, name_filter))
        for m in modules:
            results.append(build.test_module(m, name_filter))
            if m.is_android_app:
                build.kotlinc.close()
        build.kotlinc.close()
    finally:
        from .dexing import finish_background
        finish_background()  # also when a module fails to compile: the dex is kept for the next run
    passed = sum(r.passed for r in results)
    failed = sum(r.failed for r in results) + sum(1 for r in results if r.crashed)
    skipped = sum(r.skipped for r in results)
    for r in results:
        if r.passed or r.failed or r.skipped or r.crashed:
            print(f"{r.module}: {r.passed} passed, {r.failed} failed, {r.skipped} skipped"
                  + (" (test JVM crashed)" if r.crashed else ""))
    print(f"{passed} passed, {failed} failed, {skipped} skipped")
    return 0 if failed == 0 else 1


ARRIVAL_DEFAULT = 10_000


def arrival_count(rest: list[str]) -> int:
    """The message count of `bench --arrival [N]`: N, or ARRIVAL_DEFAULT without one."""
    i = rest.index("--arrival")
    given = rest[i + 1] if i + 1 < len(rest) else None
    if given is None:
        return ARRIVAL_DEFAULT
    if not given.isdigit() or int(given) < 1:
        raise BuildError(f"bench --arrival takes a message count (a whole number >= 1), not {given!r}")
    return int(given)


def bench_arrival(build: Build, count: int) -> int:
    """
    `./build bench --arrival [N]`: the app's arrival-to-touch benchmark (ArrivalToTouchBench, a Robolectric class the
    test suite skips unless HAPTICON_BENCH_ARRIVAL names a message count). Its table shows as it runs and stays in
    out/app/bench-arrival.txt. HAPTICON_BENCH_JVM_ARGS adds options to its JVM (another garbage collector).
    """
    from .android import AndroidApp
    os.environ["HAPTICON_BENCH_ARRIVAL"] = str(count)
    # e.g. "-XX:-UseParallelGC -XX:+UseZGC": the test JVM's collector is the build's (ParallelGC) unless this says otherwise.
    extra = tuple(os.environ.get("HAPTICON_BENCH_JVM_ARGS", "").split())
    result = AndroidApp(build, app_module(build.project)).test(r"\.ArrivalToTouchBench\.", extra_jvm_args=extra)
    build.kotlinc.close()
    if result.failed or result.crashed or not result.passed:
        print(f"the arrival bench did not run to the end ({result.passed} passed, {result.failed} failed, "
              f"{result.skipped} skipped); see out/app/test.log", file=sys.stderr)
        return 1
    return 0


def record_screenshots(build: Build, rest: list[str]) -> int:
    """`./build screenshots`: the app's screenshot tests (class names ending in ScreenshotTest) in record mode."""
    from .android import AndroidApp
    name_filter = rest[rest.index("--tests") + 1] if "--tests" in rest else r"ScreenshotTest\b"
    result = AndroidApp(build, app_module(build.project)).test(name_filter, record_screenshots=True)
    build.kotlinc.close()
    failed = result.failed + (1 if result.crashed else 0)
    print(f"{result.passed} passed, {failed} failed, {result.skipped} skipped; "
          f"screens in {os.path.join('docs', 'images', 'screens')}")
    return 0 if failed == 0 else 1


def build_tool_tests(root: str, name_filter: str | None) -> TestResult:
    """The offline build's own Python tests (tools/offline-build/tests)."""
    result = TestResult("tools/offline-build")
    cmd = [sys.executable, "-B", "-m", "unittest", "discover", "-s", "tests", "-t", "."]
    if name_filter:
        cmd += ["-k", name_filter]
    with ui.Stage("test tools/offline-build"):
        p = subprocess.run(cmd, cwd=os.path.join(root, "tools", "offline-build"), text=True,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    ran = re.search(r"Ran (\d+) tests?", p.stdout)
    if not ran:
        print(p.stdout, file=sys.stderr)
        result.crashed = True
        return result
    counts = {k: int(v) for k, v in re.findall(r"(failures|errors|skipped)=(\d+)", p.stdout)}
    result.failed = counts.get("failures", 0) + counts.get("errors", 0)
    result.skipped = counts.get("skipped", 0)
    result.passed = int(ran.group(1)) - result.failed - result.skipped
    if p.returncode != 0:
        print(p.stdout, file=sys.stderr)
    return result


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
