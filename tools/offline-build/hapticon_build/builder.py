"""Builds modules in dependency order: classpaths, Kotlin compilation, resources, tests."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, field

from .errors import BuildError
from .kotlin import KotlinCompiler, fingerprint
from .maven import Repository
from .project import Dependency, Module, Project
from .resolver import Resolver
from .toolchain import Toolchain
from .ui import Stage, StageTimes, info

MAIN_COMPILE = ("implementation", "api", "compileOnly")
MAIN_RUNTIME = ("implementation", "api", "runtimeOnly")
TEST_COMPILE = ("testImplementation", "testCompileOnly")
TEST_RUNTIME = ("testImplementation", "testRuntimeOnly")
# Before a module's compilation has been timed on this machine, its estimate: seconds of kotlinc per source file
# (a first compilation in a fresh compiler process, JIT warm-up included), measured on 2026-11-28 (docs/build.md).
COMPILE_S_PER_FILE = 1.0
KSP_S = 30.0


@dataclass
class Outputs:
    """What a compiled source set contributes to classpaths."""
    classes: str
    resources: list[str] = field(default_factory=list)

    @property
    def entries(self) -> list[str]:
        return [self.classes] + self.resources


@dataclass
class TestResult:
    module: str
    passed: int = 0
    failed: int = 0
    skipped: int = 0
    crashed: bool = False


class Build:
    def __init__(self, project: Project, repo: Repository | None = None):
        self.project = project
        self.root = project.root
        self.out = os.path.join(self.root, "out")
        self.cache = os.path.join(self.root, ".build-cache")
        self.repo = repo or Repository()
        self.tools = Toolchain(project, self.repo, self.cache)
        self.kotlinc = KotlinCompiler(self.tools, os.path.join(self.out, "tmp"))
        self.stage_times = StageTimes(os.path.join(self.cache, "stage-times.json"))
        self._classpaths: dict[tuple, list[str]] = {}
        self._outputs: dict[tuple, Outputs] = {}

    # -- dependency declarations ------------------------------------------------------------------
    def platform(self, module: Module) -> str:
        return "android" if module.is_android else "jvm"

    def _implicit(self, module: Module) -> list[Dependency]:
        # The Kotlin Gradle plugin (and AGP's built-in Kotlin) adds kotlin-stdlib to every Kotlin module.
        stdlib = self.project.catalog.library("kotlin-stdlib")
        return [Dependency("api", library=stdlib)]

    def _external_roots(self, module: Module, configurations: tuple, exported_only: bool, seen=None) -> list:
        """External coordinates visible to `module` for `configurations`, following project dependencies.

        Through a project dependency only its `api` externals are visible at compile time (Gradle's
        compile classpath), and its api+implementation+runtimeOnly ones at run time."""
        seen = seen if seen is not None else set()
        if module.path in seen:
            return []
        seen.add(module.path)
        roots = []
        for d in module.dependencies + self._implicit(module):
            if d.configuration not in configurations or d.configuration == "ksp":
                continue
            if d.library:
                roots.append((d.library, d.excludes))
            elif d.project:
                dep = self.project.module(d.project)
                inherited = ("api",) if exported_only else MAIN_RUNTIME
                roots += self._external_roots(dep, inherited, exported_only, seen)
        return roots

    def _project_outputs(self, module: Module, configurations: tuple, exported_only: bool, seen=None) -> list[str]:
        seen = seen if seen is not None else set()
        entries = []
        for d in module.dependencies:
            if d.configuration in configurations and d.project and d.project not in seen:
                seen.add(d.project)
                dep = self.project.module(d.project)
                entries += self.compile_module(dep, "main").entries
                inherited = ("api",) if exported_only else MAIN_RUNTIME
                entries += self._project_outputs(dep, inherited, exported_only, seen)
        return entries

    def external_classpath(self, module: Module, scope: str) -> list[str]:
        """Resolved, downloaded artifact files (jars and aars) for scope main|test × compile|runtime."""
        key = (module.path, scope)
        if key in self._classpaths:
            return self._classpaths[key]
        source_set, use = scope.split("-")
        configurations = MAIN_COMPILE if use == "compile" else MAIN_RUNTIME
        if module.is_android:
            configurations += ("debugImplementation",)
        if source_set == "test":
            configurations += TEST_COMPILE if use == "compile" else TEST_RUNTIME
        roots = self._external_roots(module, configurations, exported_only=(use == "compile"))
        unique = {}
        for c, excludes in roots:
            key = (c.group, c.name, c.version)
            unique[key] = unique.get(key, excludes) & excludes  # excluded only if excluded on every path
        resolver = Resolver(self.repo, self.platform(module))
        artifacts = resolver.resolve([k + (ex,) for k, ex in unique.items()])
        files = [f for a in artifacts for f in a.files]
        paths = self.repo.fetch_all(files)
        lock = os.path.join(self.out, "resolved", f"{module.name}-{scope}.txt")
        os.makedirs(os.path.dirname(lock), exist_ok=True)
        with open(lock, "w") as f:
            f.write("".join(f"{a.coordinate}\n" for a in artifacts))
        self._classpaths[key] = paths
        return paths

    def jars(self, module: Module, scope: str) -> list[str]:
        """Classpath jars for a scope; AARs contribute their exploded classes.jar and libs/*.jar."""
        out = []
        for p in self.external_classpath(module, scope):
            out += self.explode_aar(p)["jars"] if p.endswith(".aar") else [p]
        return out

    def explode_aar(self, aar: str) -> dict:
        name = os.path.basename(aar).removesuffix(".aar")
        d = os.path.join(self.cache, "aars", name)
        if not os.path.exists(os.path.join(d, ".done")):
            shutil.rmtree(d, ignore_errors=True)
            os.makedirs(d)
            import zipfile
            with zipfile.ZipFile(aar) as z:
                z.extractall(d)
            open(os.path.join(d, ".done"), "w").close()
        jars = [os.path.join(d, "classes.jar")] if os.path.exists(os.path.join(d, "classes.jar")) else []
        libs = os.path.join(d, "libs")
        if os.path.isdir(libs):
            jars += sorted(os.path.join(libs, j) for j in os.listdir(libs) if j.endswith(".jar"))
        res = os.path.join(d, "res")
        return {"dir": d, "jars": jars, "res": res if os.path.isdir(res) and os.listdir(res) else None,
                "manifest": os.path.join(d, "AndroidManifest.xml")}

    # -- compilation ------------------------------------------------------------------------------
    def sources(self, module: Module, source_set: str) -> list[str]:
        found = []
        for lang in ("kotlin", "java"):
            base = os.path.join(module.directory, "src", source_set, lang)
            for root, _dirs, files in os.walk(base):
                found += [os.path.join(root, f) for f in files if f.endswith(".kt")]
        return sorted(found)

    def resource_dirs(self, module: Module, source_set: str) -> list[str]:
        d = os.path.join(module.directory, "src", source_set, "resources")
        return [d] if os.path.isdir(d) else []

    def compile_classpath(self, module: Module, source_set: str, extra: list[str] = ()) -> list[str]:
        cp = list(extra)
        if module.is_android:
            cp.append(self.tools.android_jar)
        if source_set == "test":
            cp += self.compile_module(module, "main").entries
            cp += self._project_outputs(module, MAIN_RUNTIME + TEST_COMPILE, exported_only=False)
            cp += self.jars(module, "test-compile")
        else:
            cp += self._project_outputs(module, MAIN_COMPILE, exported_only=True)
            cp += self.jars(module, "main-compile")
        return cp

    def compile_module(self, module: Module, source_set: str = "main", extra_classpath: list[str] = (),
                       extra_sources: list[str] = ()) -> Outputs:
        key = (module.path, source_set)
        if key in self._outputs:
            return self._outputs[key]
        if (module.is_android_app or module.is_android_test) and source_set == "main" and not extra_classpath:
            from .instrumentation import apk_builder
            return apk_builder(self, module).compile_main()
        sources = self.sources(module, source_set) + list(extra_sources)
        out_dir = os.path.join(self.out, module.name, "classes", source_set)
        classpath = self.compile_classpath(module, source_set, list(extra_classpath))
        if module.uses_ksp and source_set == "main":
            sources += self.run_ksp(module, sources, classpath)
        resources = self.resource_dirs(module, source_set)
        stamp = os.path.join(self.out, module.name, f"{source_set}.stamp")
        plugins = [self.tools.compiler_plugin(alias) for alias in module.compiler_plugins]
        fp = fingerprint(sources, classpath, str(module.explicit_api), plugins, source_set)
        if not sources:
            os.makedirs(out_dir, exist_ok=True)
        elif not (os.path.exists(stamp) and open(stamp).read() == fp):
            stage = f"compile {module.path} {source_set}"
            with Stage(f"{stage} ({len(sources)} files)", self.stage_times.expected(stage, len(sources) * COMPILE_S_PER_FILE),
                       self.stage_times, stage):
                shutil.rmtree(out_dir, ignore_errors=True)
                os.makedirs(out_dir)
                friends = [self._outputs[(module.path, "main")].classes] if source_set == "test" else []
                self.kotlinc.compile(sources=sources, classpath=classpath, output=out_dir,
                                     module_name=f"{self.project.name}-{module.name}" + ("" if source_set == "main" else "-test"),
                                     explicit_api=module.explicit_api and source_set == "main",
                                     plugins=plugins, friend_paths=friends)
                with open(stamp, "w") as f:
                    f.write(fp)
        outputs = Outputs(out_dir, resources)
        self._outputs[key] = outputs
        return outputs

    def run_ksp(self, module: Module, sources: list[str], classpath: list[str]) -> list[str]:
        """Runs the module's `ksp(...)` processors (e.g. Room) and returns the Kotlin sources they generate."""
        roots = [(d.library.group, d.library.name, d.library.version) for d in module.deps("ksp") if d.library]
        if not roots:
            return []
        processors = Resolver(self.repo, "jvm").resolve(roots)
        # The KSP tool provides its own API; a second copy on the processor path breaks class identity.
        processor_jars = self.repo.fetch_all([f for a in processors for f in a.files
                                              if f.endswith(".jar") and a.name != "symbol-processing-api"])
        base = os.path.join(self.out, module.name, "ksp")
        stamp = os.path.join(base, "ksp.stamp")
        fp = fingerprint(sources, classpath, processor_jars, str(sorted(module.ksp_args.items())))
        generated = os.path.join(base, "kotlin")
        if not (os.path.exists(stamp) and open(stamp).read() == fp):
            with Stage(f"ksp {module.path}", self.stage_times.expected(f"ksp {module.path}", KSP_S), self.stage_times):
                shutil.rmtree(base, ignore_errors=True)
                os.makedirs(base)
                source_roots = sorted({os.path.join(module.directory, "src", "main", "kotlin")})
                cmd = [self.tools.java, "-Xmx2g", "-cp", os.pathsep.join(self.tools.ksp),
                       "com.google.devtools.ksp.cmdline.KSPJvmMain",
                       "-jvm-target=17", f"-module-name={self.project.name}-{module.name}",
                       "-source-roots=" + os.pathsep.join(source_roots), f"-project-base-dir={module.directory}",
                       f"-output-base-dir={base}", f"-caches-dir={base}/caches", f"-class-output-dir={base}/classes",
                       f"-kotlin-output-dir={generated}", f"-java-output-dir={base}/java",
                       f"-resource-output-dir={base}/resources", f"-jdk-home={self.tools.java_home}",
                       "-language-version=2.3", "-api-version=2.3",
                       "-libraries=" + os.pathsep.join(classpath)]
                if module.ksp_args:
                    cmd.append("-processor-options=" + os.pathsep.join(f"{k}={v}" for k, v in module.ksp_args.items()))
                cmd.append(os.pathsep.join(processor_jars))
                from .toolchain import run
                run(cmd, f"KSP for {module.path}", log=os.path.join(base, "ksp.log"))
                with open(stamp, "w") as f:
                    f.write(fp)
        return sorted(os.path.join(r, f) for r, _d, fs in os.walk(generated) for f in fs if f.endswith(".kt"))

    def runtime_classpath(self, module: Module, source_set: str) -> list[str]:
        cp = []
        if source_set == "test":
            cp += self.compile_module(module, "test").entries
        cp += self.compile_module(module, "main").entries
        configurations = MAIN_RUNTIME + (TEST_RUNTIME if source_set == "test" else ())
        cp += self._project_outputs(module, configurations, exported_only=False)
        cp += self.jars(module, f"{source_set}-runtime")
        return cp

    # -- tests ------------------------------------------------------------------------------------
    def test_module(self, module: Module, name_filter: str | None = None) -> TestResult:
        if module.is_android_test:
            return TestResult(module.path)  # its tests run on a phone (./build device-check), never on the JVM
        if module.is_android:
            from .android import AndroidApp
            return AndroidApp(self, module).test(name_filter)
        if not self.sources(module, "test"):
            return TestResult(module.path)
        classes = self.compile_module(module, "test").classes
        return self.run_junit(module, classes, self.runtime_classpath(module, "test"), name_filter)

    def run_junit(self, module: Module, test_classes: str, classpath: list[str], name_filter: str | None,
                  jvm_args: list[str] = (), java: str | None = None, label: str = "") -> TestResult:
        junit = [p for p in classpath if re.search(r"/junit-4[^/]*\.jar$", p)]
        if not junit:
            raise BuildError(f"{module.path} has tests but no junit4 in testImplementation")
        helper = self.tools.helper_classes("TestMain", junit)
        cmd = [java or self.tools.java, "-Xmx3g", "-XX:+UseParallelGC", "-Djava.awt.headless=true", *jvm_args,
               "-cp", os.pathsep.join([helper] + classpath), "TestMain", test_classes]
        if name_filter:
            cmd.append(name_filter)
        result = TestResult(module.path)
        with Stage(f"test {module.path}{label}"):
            log_path = os.path.join(self.out, module.name, f"test{label.replace(' ', '-')}.log")
            with open(log_path, "w") as log:
                p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=module.directory)
                for line in p.stdout:
                    log.write(line)
                    m = re.match(r"TESTS passed=(\d+) failed=(\d+) skipped=(\d+)", line)
                    if m:
                        result.passed, result.failed, result.skipped = map(int, m.groups())
                        info(line.strip().removeprefix("TESTS "))
                    elif line.startswith(("FAILED", "    ", "SKIPPED")) or "Exception" in line:
                        print(line, end="", file=sys.stderr)
                p.wait()
            if p.returncode != 0 and result.failed == 0:
                result.crashed = True
                print(f"  test JVM for {module.path} exited {p.returncode} without a result; log: {log_path}",
                      file=sys.stderr)
        return result
