"""Kotlin compilation through one warm compiler process per build (see java/KotlinWorker.java)."""
from __future__ import annotations

import atexit
import hashlib
import os
import subprocess

from .errors import BuildError
from .toolchain import Toolchain


class KotlinCompiler:
    def __init__(self, tools: Toolchain, work: str):
        self.tools = tools
        self.work = work
        self._process: subprocess.Popen | None = None
        self._jobs = 0

    def _worker(self) -> subprocess.Popen:
        if self._process is None or self._process.poll() is not None:
            cp = self.tools.kotlin_compiler
            helper = self.tools.helper_classes("KotlinWorker", cp)
            self._process = subprocess.Popen(
                [self.tools.java, "-Xmx3g", "-Xss8m", "-XX:+UseParallelGC", "-Didea.io.use.nio2=true",
                 "-cp", os.pathsep.join([helper] + cp), "KotlinWorker"],
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
            atexit.register(self.close)
        return self._process

    def close(self) -> None:
        if self._process and self._process.poll() is None:
            self._process.stdin.close()
            self._process.wait(timeout=30)

    def compile(self, *, sources: list[str], classpath: list[str], output: str, module_name: str,
                explicit_api: bool = False, plugins: list[str] = (), friend_paths: list[str] = (),
                jvm_target: str = "17") -> None:
        """Compiles `sources` into the class directory `output`; raises BuildError with the diagnostics.

        `plugins` are compiler plugin jars (Compose, kotlinx-serialization), passed as `-Xplugin=` the way
        the Kotlin Gradle plugin passes them."""
        args = compiler_arguments(sources=sources, classpath=classpath, output=output, module_name=module_name,
                                  explicit_api=explicit_api, plugins=plugins, friend_paths=friend_paths,
                                  jvm_target=jvm_target)
        self._jobs += 1
        os.makedirs(self.work, exist_ok=True)
        argfile = os.path.join(self.work, f"kotlinc-{module_name}-{self._jobs}.args")
        with open(argfile, "w") as f:
            f.write("\n".join(args) + "\n")
        worker = self._worker()
        worker.stdin.write(argfile + "\n")
        worker.stdin.flush()
        line = worker.stdout.readline()
        if not line.startswith("EXIT "):
            raise BuildError(f"the Kotlin compiler worker died while compiling {module_name}")
        code = int(line.split()[1])
        log = open(argfile + ".log").read()
        if code != 0:
            errors = [l for l in log.splitlines() if "error:" in l or l.startswith("e:")] or log.splitlines()[-30:]
            raise BuildError(f"Kotlin compilation of {module_name} failed:\n" + "\n".join(errors[:60]))


def compiler_arguments(*, sources: list[str], classpath: list[str], output: str, module_name: str,
                       explicit_api: bool = False, plugins: list[str] = (), friend_paths: list[str] = (),
                       jvm_target: str = "17") -> list[str]:
    """The kotlinc command line for one compilation (without the compiler's own class path)."""
    args = ["-no-stdlib", "-no-reflect", "-jvm-target", jvm_target, "-module-name", module_name,
            "-Xjdk-release=" + jvm_target, "-nowarn",
            "-classpath", os.pathsep.join(classpath), "-d", output]
    if explicit_api:
        args.append("-Xexplicit-api=strict")
    args += ["-Xplugin=" + jar for jar in plugins]
    if friend_paths:
        args.append("-Xfriend-paths=" + ",".join(friend_paths))
    return args + list(sources)


def fingerprint(*parts) -> str:
    """Content hash of files (by path) and strings, for up-to-date checks."""
    h = hashlib.sha1()
    for part in parts:
        if isinstance(part, (list, tuple)):
            for p in part:
                _feed(h, p)
        else:
            _feed(h, part)
    return h.hexdigest()


def _feed(h, item) -> None:
    h.update(str(item).encode() + b"\0")
    if isinstance(item, str) and os.path.isfile(item):
        st = os.stat(item)
        h.update(f"{st.st_size}:{st.st_mtime_ns}".encode())
    elif isinstance(item, str) and os.path.isdir(item):
        for root, _dirs, files in sorted(os.walk(item)):
            for f in sorted(files):
                p = os.path.join(root, f)
                st = os.stat(p)
                h.update(f"{p}:{st.st_size}:{st.st_mtime_ns}".encode())
