"""The Android application pipeline AGP would run: aapt2, manifest merger, kotlinc, D8, apksig.

Resource ids are generated non-final (`--non-final-ids`, AGP's default since 8.0) so compiled app
classes never inline ids, and the same classes run under Robolectric with the test resource table.
"""
from __future__ import annotations

import fnmatch
import hashlib
import json
import os
import re
import shutil
import struct
import subprocess
import zipfile
from dataclasses import dataclass

from .builder import Build, Outputs, TestResult
from .dexing import D8Tool, dex_files, shared_dex_cache, dex_libraries, dex_modules, library_globals, module_jar, start_in_background
from .errors import BuildError
from .kotlin import fingerprint
from .project import Module
from .toolchain import fetch_java_runtime, java_for_sdk36, run
from .ui import Stage, info

# AGP's default packaging excludes for Java resources taken from jars.
JAVA_RESOURCE_EXCLUDES = [
    "META-INF/LICENSE", "META-INF/LICENSE.txt", "META-INF/MANIFEST.MF", "META-INF/NOTICE", "META-INF/NOTICE.txt",
    "META-INF/*.DSA", "META-INF/*.EC", "META-INF/*.SF", "META-INF/*.RSA", "META-INF/maven/*",
    "META-INF/proguard/*", "META-INF/com.android.tools/*", "NOTICE", "NOTICE.txt", "LICENSE.txt", "LICENSE",
    "*/.svn/*", "*/CVS/*", "*/SCCS/*", ".*", "*/.*", "*~", "*/thumbs.db", "*/picasa.ini", "*/about.html",
    "*/package.html", "*/overview.html", "*/protobuf.meta", "_*", "*/_*", "*.kotlin_metadata",
    "*.class", "META-INF/versions/*/module-info.class",
]
MERGED_JAVA_RESOURCES = ("META-INF/services/",)  # concatenated, as AGP's default merges do
# Estimates before a stage has been timed on this machine (docs/build.md, 2026-11-28).
RESOURCES_S = 15.0
PACKAGE_S = 10.0


def excluded(name: str) -> bool:
    return name.endswith("/") or any(fnmatch.fnmatchcase(name, p) for p in JAVA_RESOURCE_EXCLUDES)


class AndroidApp:
    def __init__(self, build: Build, module: Module):
        self.b = build
        self.m = module
        self.tools = build.tools
        self.out = os.path.join(build.out, module.name)
        self.namespace = module.android["namespace"]
        self.application_id = module.android.get("applicationId", self.namespace)
        self.min_sdk = module.android["minSdk"]
        self.target_sdk = module.android["targetSdk"]
        self.version_code = module.android.get("versionCode", "1")
        self.version_name = module.android.get("versionName", "1.0")
        self.src = os.path.join(module.directory, "src", "main")
        self.apk = os.path.join(self.out, f"{build.project.name}-debug.apk")

    # -- resources --------------------------------------------------------------------------------
    def _libraries(self, scope: str) -> list[dict]:
        """Everything whose resources and manifest merge into this module's: AARs and project Android libraries."""
        aars = [self.b.explode_aar(p) for p in self.b.external_classpath(self.m, scope) if p.endswith(".aar")]
        return aars + [self._project_library(m) for m in self._project_android_libraries(self.m, set())]

    def _project_android_libraries(self, module: Module, seen: set) -> list[Module]:
        found = []
        for d in module.dependencies:
            if d.project and d.project not in seen and not d.configuration.startswith("test"):
                seen.add(d.project)
                dep = self.b.project.module(d.project)
                if dep.is_android_library:
                    found.append(dep)
                found += self._project_android_libraries(dep, seen)
        return found

    def _project_library(self, library: Module) -> dict:
        src = os.path.join(library.directory, "src", "main")
        work = os.path.join(self.b.out, library.name, "intermediates")
        os.makedirs(work, exist_ok=True)
        manifest = os.path.join(work, "AndroidManifest.xml")
        main = os.path.join(src, "AndroidManifest.xml")
        text = open(main).read() if os.path.exists(main) else '<manifest xmlns:android="http://schemas.android.com/apk/res/android" />'
        with open(manifest, "w") as f:
            f.write(re.sub(r"<manifest\b", f'<manifest package="{library.android["namespace"]}"', text, count=1))
        res = os.path.join(src, "res")
        return {"dir": work, "jars": [], "manifest": manifest, "project": library.name,
                "res": res if os.path.isdir(res) and os.listdir(res) else None}

    def _compile_library_resources(self, libs: list[dict]) -> list[str]:
        zips = []
        pending = []
        for lib in libs:
            if not lib["res"]:
                continue
            if lib.get("project"):  # project sources change: compiled every time, they are small
                z = os.path.join(lib["dir"], "res.zip")
                run([self.tools.aapt2, "compile", "--dir", lib["res"], "-o", z], f"aapt2 compile of {lib['project']}")
                zips.append(z)
                continue
            z = os.path.join(self.b.cache, "aapt2", os.path.basename(lib["dir"]) + ".zip")
            zips.append(z)
            if not os.path.exists(z):
                pending.append((lib["res"], z))
        if pending:
            os.makedirs(os.path.join(self.b.cache, "aapt2"), exist_ok=True)
            procs = []
            for res, z in pending:  # two at a time: the machines have two cores
                procs.append((subprocess.Popen([self.tools.aapt2, "compile", "--dir", res, "-o", z + ".tmp"],
                                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True), z))
                if len(procs) == 2:
                    self._wait_aapt2(procs)
            self._wait_aapt2(procs)
        return zips

    @staticmethod
    def _wait_aapt2(procs):
        for p, z in procs:
            output = p.communicate()[0]
            if p.returncode != 0:
                raise BuildError(f"aapt2 compile for {z} failed:\n{output}")
            os.replace(z + ".tmp", z)
        procs.clear()

    def _main_manifest(self) -> str:
        """The module's own manifest, before the libraries' are merged into it."""
        main = os.path.join(self.src, "AndroidManifest.xml")
        if not os.path.exists(main):
            raise BuildError(f"{main} not found")
        text = open(main).read()
        if "<uses-sdk" in text:
            raise BuildError(f"{main}: declare minSdk/targetSdk in build.gradle.kts, not <uses-sdk>")
        return text

    def _merge_manifest(self, libs: list[dict], out: str) -> str:
        text = self._main_manifest()
        # AGP injects the namespace as the package; the merger needs it on the main manifest.
        text = re.sub(r"<manifest\b", f'<manifest package="{self.namespace}"', text, count=1)
        os.makedirs(out, exist_ok=True)
        staged = os.path.join(out, "main-AndroidManifest.xml")
        with open(staged, "w") as f:
            f.write(text)
        merged = os.path.join(out, "AndroidManifest.xml")
        lib_manifests = [l["manifest"] for l in libs if os.path.exists(l["manifest"])]
        run([self.tools.java, "-cp", os.pathsep.join(self.tools.manifest_merger), "com.android.manifmerger.Merger",
             "--main", staged, "--libs", os.pathsep.join(lib_manifests),
             "--property", f"MIN_SDK_VERSION={self.min_sdk}", "--property", f"TARGET_SDK_VERSION={self.target_sdk}",
             "--property", f"VERSION_CODE={self.version_code}", "--property", f"VERSION_NAME={self.version_name}",
             "--placeholder", f"applicationId={self.application_id}", "--placeholder", f"packageName={self.application_id}",
             "--remove-tools-declarations", "--out", merged], "manifest merge", log=os.path.join(out, "merger.log"))
        return merged

    def _link(self, scope: str, work: str, release: bool = False) -> tuple[str, str]:
        """Links resources for `scope` (main-runtime or test-runtime); returns (resource apk, R classes jar).
        A release link is not debuggable and writes aapt2's keep rules for the classes the manifest and
        layouts name (`work/aapt2-rules.pro`), as AGP feeds R8."""
        libs = self._libraries(scope)
        lib_zips = self._compile_library_resources(libs)
        app_res = os.path.join(self.src, "res")
        app_zip = os.path.join(work, "app-res.zip")
        os.makedirs(work, exist_ok=True)
        if os.path.isdir(app_res):
            run([self.tools.aapt2, "compile", "--dir", app_res, "-o", app_zip], "aapt2 compile of app resources")
        manifest = self._merge_manifest(libs, work)
        packages = set()
        for lib in libs:
            if lib["res"] and os.path.exists(lib["manifest"]):
                m = re.search(r'package="([^"]+)"', open(lib["manifest"]).read())
                if m:
                    packages.add(m.group(1))
        packages.discard(self.namespace)
        gen = os.path.join(work, "gen")
        shutil.rmtree(gen, ignore_errors=True)
        res_apk = os.path.join(work, "resources.apk")
        overlays = []
        for z in lib_zips + ([app_zip] if os.path.isdir(app_res) else []):  # the app's own resources win
            overlays += ["-R", z]
        cmd = [self.tools.aapt2, "link", "-I", self.tools.android_jar, "--manifest", manifest, "--auto-add-overlay",
               *overlays, "--java", gen, "--non-final-ids", "--min-sdk-version", self.min_sdk,
               "--target-sdk-version", self.target_sdk, "--version-code", self.version_code,
               "--version-name", self.version_name, "--rename-manifest-package", self.application_id,
               "-o", res_apk]
        # aapt2's keep rules for the classes the manifest and layouts name: the release build's R8 needs them.
        cmd += ["--proguard", os.path.join(work, "aapt2-rules.pro")] + ([] if release else ["--debug-mode"])
        if packages:
            cmd += ["--extra-packages", ":".join(sorted(packages))]
        run(cmd, "aapt2 link", log=os.path.join(work, "aapt2-link.log"))
        r_sources = [os.path.join(r, f) for r, _d, fs in os.walk(gen) for f in fs if f.endswith(".java")]
        r_classes = os.path.join(work, "r-classes")
        shutil.rmtree(r_classes, ignore_errors=True)
        run([self.tools.javac, "--release", "11", "-nowarn", "-encoding", "UTF-8", "-d", r_classes, *r_sources],
            "javac of R classes")
        r_jar = os.path.join(work, "R.jar")
        _jar_directory(r_classes, r_jar)
        return res_apk, r_jar

    def _resource_sources(self) -> list[str]:
        modules = [self.m] + self._project_android_libraries(self.m, set())
        return [os.path.join(m.directory, "src", "main", p) for m in modules for p in ("res", "AndroidManifest.xml")]

    # -- compile ----------------------------------------------------------------------------------
    def compile_main(self) -> Outputs:
        work = os.path.join(self.out, "intermediates", "main")
        fp = fingerprint(self.b.external_classpath(self.m, "main-runtime"), self._resource_sources(), str(self.m.android))
        stamp = os.path.join(work, "resources.stamp")
        self.res_apk, self.r_jar = os.path.join(work, "resources.apk"), os.path.join(work, "R.jar")
        fresh = all(os.path.exists(f) for f in (stamp, self.r_jar, os.path.join(work, "aapt2-rules.pro")))
        if not (fresh and open(stamp).read() == fp):
            key = f"resources {self.m.path}"
            with Stage(key, self.b.stage_times.expected(key, RESOURCES_S), self.b.stage_times):
                self._link("main-runtime", work)
                with open(stamp, "w") as f:
                    f.write(fp)
        outputs = self.b.compile_module(self.m, "main", extra_classpath=[self.r_jar])
        return outputs

    # -- APK --------------------------------------------------------------------------------------
    def assemble(self) -> str:
        self.start_library_dex()
        classes = self.b.compile_module(self.m, "main")
        if not hasattr(self, "r_jar"):
            self.compile_main()
        runtime = self.b.runtime_classpath(self.m, "main")
        project_entries = [e for e in runtime if e.startswith(self.b.out) or os.path.isdir(e)]
        library_jars, _consumer_rules = self._library_inputs()
        stamp = self.apk + ".stamp"
        fp = fingerprint(project_entries, library_jars, self.res_apk, self.r_jar)
        if os.path.exists(self.apk) and os.path.exists(stamp) and open(stamp).read() == fp:
            info(f"{os.path.relpath(self.apk, self.b.root)} is up to date")
            return self.apk
        with Stage("dex"):
            dexes = self._dex(project_entries, library_jars)
        with Stage("package and sign", self.b.stage_times.expected("package and sign", PACKAGE_S), self.b.stage_times):
            unsigned = os.path.join(self.out, "intermediates", "unsigned.apk")
            shutil.copyfile(self.res_apk, unsigned)
            # Deflate level 9 (zlib's best; Python's default is 6): about 30 KB smaller on our dex.
            with zipfile.ZipFile(unsigned, "a", zipfile.ZIP_DEFLATED, compresslevel=9) as apk:
                for i, dex in enumerate(dexes):
                    apk.write(dex, "classes.dex" if i == 0 else f"classes{i + 1}.dex")
                count = self._add_java_resources(apk, project_entries + library_jars)
                natives = self._add_native_libraries(apk)
            info(f"{count} Java resources, {natives} native libraries packaged")
            self._sign(unsigned, self.apk)
        with Stage("verify APK"):
            self.verify(self.apk)
        with open(stamp, "w") as f:
            f.write(fp)
        return self.apk

    # -- release APK -------------------------------------------------------------------------------
    def assemble_release(self, signing: "Signing") -> str:
        """The release APK: resources linked for release, the whole program (app + libraries) shrunk and
        optimised by R8 with app/proguard-rules.pro, the libraries' own consumer rules and aapt2's rules,
        signed with `signing` and verified. The R8 output then goes through [smoke_check]: classes and members reached by name."""
        self.b.compile_module(self.m, "main")
        if not hasattr(self, "r_jar"):
            self.compile_main()
        work = os.path.join(self.out, "intermediates", "release")
        with Stage("resources (release)"):
            res_apk, r_jar = self._link("main-runtime", work, release=True)
        runtime = self.b.runtime_classpath(self.m, "main")
        project_entries = [e for e in runtime if e.startswith(self.b.out) or os.path.isdir(e)]
        library_jars, consumer_rules = self._library_inputs()
        program = os.path.join(work, "program.jar")
        with zipfile.ZipFile(program, "w") as z:
            for entry in project_entries:
                _add_tree(z, entry, classes_only=True)
            with zipfile.ZipFile(r_jar) as r:
                for n in r.namelist():
                    z.writestr(n, r.read(n))
        dex_out = os.path.join(work, "dex")
        rules = [os.path.join(self.m.directory, "proguard-rules.pro"), os.path.join(work, "aapt2-rules.pro")]
        rules += consumer_rules
        missing = [r for r in rules[:1] if not os.path.exists(r)]
        if missing:
            raise BuildError(f"{missing[0]} not found: the release build needs the app's keep rules")
        # R8 takes minutes: it runs again only when the program's classes, the libraries or a rule changed.
        key = hashlib.sha1()
        with zipfile.ZipFile(program) as z:
            for n in sorted(z.namelist()):
                key.update(n.encode() + z.read(n))
        for f in library_jars + rules:
            key.update(f.encode() + str(os.path.getsize(f)).encode())
        for f in rules:
            key.update(open(f, "rb").read())
        stamp = os.path.join(work, "r8.stamp")
        if os.path.exists(stamp) and open(stamp).read() == key.hexdigest() and os.path.isdir(dex_out):
            info("R8 output is up to date")
        else:
            self._r8(work, dex_out, rules, consumer_rules, program, library_jars)
            with open(stamp, "w") as f:
                f.write(key.hexdigest())
        # R8 also writes the Java resources it kept (kotlin/*.kotlin_builtins, …) next to the dex files.
        dex_files = sorted((os.path.join(dex_out, f) for f in os.listdir(dex_out) if f.endswith(".dex")), key=_dex_order)
        with Stage("smoke check of the R8 output"):
            mapping = os.path.join(work, "mapping.txt")
            classes, members, rewritten = smoke_check(
                dex_files, required_classes(program, os.path.join(work, "AndroidManifest.xml")),
                required_members(program, library_jars, os.path.join(self.b.cache, "field-lookups")),
                read_mapping(mapping), read_field_mapping(mapping))
            info(f"{classes} classes and {members} members reached by name found in the R8 output "
                 f"({rewritten} fields renamed by R8 together with the newUpdater/getDeclaredField names that find them)")
        apk = os.path.join(self.out, f"{self.b.project.name}-release.apk")
        with Stage("package and sign (release)"):
            unsigned = os.path.join(work, "unsigned.apk")
            shutil.copyfile(res_apk, unsigned)
            with zipfile.ZipFile(unsigned, "a", zipfile.ZIP_DEFLATED, compresslevel=9) as z:
                for i, dex in enumerate(dex_files):
                    z.write(dex, "classes.dex" if i == 0 else f"classes{i + 1}.dex")
                self._add_java_resources(z, project_entries + library_jars)
                self._add_native_libraries(z)
            self._sign_with(signing, unsigned, apk)
        with Stage("verify APK"):
            self.verify(apk, debuggable=False)
        return apk

    def _r8(self, work: str, dex_out: str, rules: list[str], consumer_rules: list[str], program: str,
            library_jars: list[str]) -> None:
        shutil.rmtree(dex_out, ignore_errors=True)
        os.makedirs(dex_out)
        args = ["--release", "--min-api", self.min_sdk, "--lib", self.tools.android_jar, "--lib", self.tools.java_home,
                "--output", dex_out, "--pg-map-output", os.path.join(work, "mapping.txt"),
                "--pg-conf-output", os.path.join(work, "configuration.txt")]
        for r in rules:
            args += ["--pg-conf", r]
        with Stage(f"R8 ({len(library_jars)} library jars, {len(consumer_rules)} consumer rule files)"):
            run([self.tools.java, "-Xmx3g", "-cp", self.tools.r8, "com.android.tools.r8.R8", *args, program,
                 *library_jars], "R8", log=os.path.join(work, "r8.log"))

    def _d8(self, args: list[str], what: str, debug: bool = False) -> None:
        run([self.tools.java, "-Xmx3g", "-cp", self.tools.r8, "com.android.tools.r8.D8", "--debug" if debug else "--release",
             "--min-api", self.min_sdk, "--lib", self.tools.android_jar, "--lib", self.tools.java_home, *args], what)

    def _dex_program(self, program: str, library_jars: list[str], library_dex: list[str], out: str) -> list[str]:
        """The module's own classes ([program], a jar) dexed by D8 into [out] against the libraries, unshrunk; the two dex
        sets must not define one class twice (e.g. a global synthetic made for both)."""
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        self._d8([*_each("--classpath", library_jars), "--output", out, program], f"D8 of {self.m.path}'s classes")
        program_dex = sorted((os.path.join(out, f) for f in os.listdir(out)), key=_dex_order)
        library_types = set().union(*(dex_type_names(open(d, "rb").read()) for d in library_dex))
        program_types = set().union(*(dex_type_names(open(d, "rb").read()) for d in program_dex))
        clash = library_types & program_types
        if clash:
            raise BuildError(f"classes defined by both {self.m.path} and its libraries: {sorted(clash)[:5]}")
        return program_dex

    def _library_inputs(self) -> tuple[list[str], list[str]]:
        """The libraries' jars (an AAR's classes.jar and libs/*.jar) and the consumer keep rules their AARs ship."""
        library_jars, consumer_rules = [], []
        for p in self.b.external_classpath(self.m, "main-runtime"):
            if p.endswith(".aar"):
                aar = self.b.explode_aar(p)
                library_jars += aar["jars"]
                rules = os.path.join(aar["dir"], "proguard.txt")
                if os.path.exists(rules):
                    consumer_rules.append(rules)
            else:
                library_jars.append(p)
        return library_jars, consumer_rules

    def _dex(self, project_entries: list[str], library_jars: list[str]) -> list[str]:
        """Dex files for the debug APK, as AGP makes them for a debuggable variant: the libraries dexed jar by jar
        and merged ([dex_libraries]: a jar is dexed once ever, the merge once per set of libraries), and each of the
        app's own modules (and its R classes) dexed alone, kept by content ([dex_modules]: an edit re-dexes only its
        module). minSdk ≥ 21 loads several dex files natively, so none of these is merged with another. Nothing is shrunk (the release APK carries the size target): the debug build runs the libraries'
        code as published. Afterwards every class the app names must be defined in the dex or by the platform,
        no class may be defined twice, and the manifest components, Room's `_Impl` classes and
        [REFLECTIVE_CLASSES] must be there."""
        work = os.path.join(self.out, "intermediates", "dex")
        os.makedirs(work, exist_ok=True)
        program = os.path.join(work, "program.jar")
        with zipfile.ZipFile(program, "w") as z:
            for entry in project_entries:
                _add_tree(z, entry, classes_only=True)
            with zipfile.ZipFile(self.r_jar) as r:
                for n in r.namelist():
                    z.writestr(n, r.read(n))
        # One jar per module (and the R classes), each dexed apart and cached by content: an edit re-dexes its module.
        module_work = os.path.join(work, "modules")
        shutil.rmtree(module_work, ignore_errors=True)
        os.makedirs(module_work)
        module_jars = []
        for i, entry in enumerate(project_entries + [self.r_jar]):
            rel = os.path.relpath(entry, self.b.out)
            name = "R" if entry == self.r_jar else rel.split(os.sep)[0] if not rel.startswith("..") else "classes"
            jar = os.path.join(module_work, f"{i:02d}-{name}.jar")
            if module_jar(entry, jar):
                module_jars.append(jar)
        tool = self._d8_tool()
        with Stage("D8 of the app's modules"):
            module_dirs = dex_modules(module_jars, tool)
        library_dex = dex_libraries(library_jars, tool)
        program_dex = [d for directory in module_dirs for d in dex_files(directory)]
        # Global synthetics (e.g. the LambdaMethod annotation D8 adds to desugared lambdas) are made apart by each
        # intermediate D8 run, the libraries' and each module's; compiled here once for all, as AGP's
        # global-synthetics merge does.
        globals_files = library_globals(library_dex) + [os.path.join(d, "globals.zip") for d in module_dirs
                                                        if os.path.exists(os.path.join(d, "globals.zip"))]
        globals_out = os.path.join(work, "globals")
        shutil.rmtree(globals_out, ignore_errors=True)
        os.makedirs(globals_out)
        if globals_files:
            with Stage("D8 of the global synthetics"):
                self._d8([*_each("--globals", globals_files), "--output", globals_out], "D8 of the global synthetics",
                         debug=True)
        program_dex += sorted((os.path.join(globals_out, f) for f in os.listdir(globals_out)), key=_dex_order)
        library_types = set().union(*(dex_type_names(open(d, "rb").read()) for d in library_dex))
        per_dex = [dex_type_names(open(d, "rb").read()) for d in program_dex]
        program_types = set().union(*per_dex)
        twice = defined_twice(per_dex)  # ART would load the first dex's and silently ignore the other
        if twice:
            raise BuildError(f"classes defined by two of the app's modules: {sorted(twice)[:5]}")
        # Two dex sets must not define one class twice (e.g. a global synthetic made for both); within the
        # libraries the merge already fails on a class two jars define.
        clash = library_types & program_types
        if clash:
            raise BuildError(f"classes defined by both the app and its libraries: {sorted(clash)[:5]}")
        with zipfile.ZipFile(self.tools.android_jar) as z:
            platform = {"L" + n.removesuffix(".class") + ";" for n in z.namelist() if n.endswith(".class")}
        # The JDK's namespaces are left to the platform: Android's libcore provides java.*, and the shared modules
        # name a few JDK-only classes (com.sun.management) on paths only the companion runs.
        named = {n for n in app_class_references(program) if not n.startswith(JDK_PREFIXES)}
        lost = sorted(named - library_types - program_types - platform)
        if lost:
            raise BuildError(f"the dex lacks {len(lost)} classes the app uses: {', '.join(lost[:5])}")
        manifest = os.path.join(os.path.dirname(self.res_apk), "AndroidManifest.xml")
        required = required_classes(program, manifest)
        missing = [n for n in required if "L" + n.replace(".", "/") + ";" not in library_types and
                   "L" + n.replace(".", "/") + ";" not in program_types]
        if missing:
            raise BuildError(f"the dex lacks classes reached by name: {', '.join(missing)}")
        info(f"{len(named)} classes the app names and {len(required)} reached by name are defined; "
             f"{len(library_types)} library and {len(program_types)} app classes, none twice")
        return library_dex + program_dex

    def _d8_tool(self) -> D8Tool:
        helper = self.tools.helper_classes("LibraryDexer", [self.tools.r8])
        return D8Tool(java=self.tools.java, classpath=[helper, self.tools.r8], r8_jar=self.tools.r8,
                      android_jar=self.tools.android_jar, java_home=self.tools.java_home, min_sdk=self.min_sdk,
                      cache=self.b.cache, threads=max(1, os.cpu_count() or 1), shared=shared_dex_cache())

    def start_library_dex(self) -> None:
        """Starts the debug APK's library dex in the background ([start_in_background]) when it is not cached: it
        needs only the resolved libraries, so it runs beside the compilation (or tests) that come first."""
        start_in_background(self._library_inputs()[0], self._d8_tool())

    def _add_java_resources(self, apk: zipfile.ZipFile, entries: list[str]) -> int:
        taken: dict[str, bytes] = {}
        for entry in entries:
            for name, read in _iter_files(entry):
                if excluded(name):
                    continue
                data = read()
                if name in taken:
                    if name.startswith(MERGED_JAVA_RESOURCES) and data not in taken[name]:
                        taken[name] = taken[name].rstrip(b"\n") + b"\n" + data
                    continue  # first one wins, as AGP's pickFirst
                taken[name] = data
        existing = set(apk.namelist())
        for name, data in sorted(taken.items()):
            if name not in existing:
                apk.writestr(name, data)
        return len(taken)

    def _add_native_libraries(self, apk: zipfile.ZipFile) -> int:
        count = 0
        for p in self.b.external_classpath(self.m, "main-runtime"):
            if p.endswith(".aar"):
                jni = os.path.join(self.b.explode_aar(p)["dir"], "jni")
                for root, _d, files in os.walk(jni):
                    for f in files:
                        if f.endswith(".so"):
                            rel = os.path.relpath(os.path.join(root, f), jni)
                            apk.write(os.path.join(root, f), "lib/" + rel, compress_type=zipfile.ZIP_STORED)
                            count += 1
        return count

    def _sign_with(self, signing: "Signing", unsigned: str, signed: str) -> None:
        """Signs with a release key; the passwords reach the signer through its environment, never argv."""
        helper = self.tools.helper_classes("ApkTool", [self.tools.apksig])
        env = dict(os.environ, HAPTICON_SIGN_STORE_PASSWORD=signing.store_password,
                   HAPTICON_SIGN_KEY_PASSWORD=signing.key_password)
        p = subprocess.run([self.tools.java, "-cp", os.pathsep.join([helper, self.tools.apksig]), "ApkTool", "sign",
                            signing.keystore, "env:HAPTICON_SIGN_STORE_PASSWORD", signing.alias, unsigned, signed,
                            self.min_sdk, "env:HAPTICON_SIGN_KEY_PASSWORD"],
                           env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if p.returncode != 0:
            raise BuildError(f"signing with {signing.keystore} (alias {signing.alias}) failed:\n{p.stdout.strip()}")

    def _sign(self, unsigned: str, signed: str) -> None:
        keystore = os.environ.get("HAPTICON_DEBUG_KEYSTORE") or os.path.join(os.path.expanduser("~"), ".android", "debug.keystore")
        if not os.path.exists(keystore):
            os.makedirs(os.path.dirname(keystore), exist_ok=True)
            run([os.path.join(self.tools.java_home, "bin", "keytool"), "-genkeypair", "-keystore", keystore,
                 "-storepass", "android", "-keypass", "android", "-alias", "androiddebugkey", "-keyalg", "RSA",
                 "-keysize", "2048", "-validity", "10000", "-dname", "CN=Android Debug,O=Android,C=US"],
                "creating the debug keystore")
        helper = self.tools.helper_classes("ApkTool", [self.tools.apksig])
        run([self.tools.java, "-cp", os.pathsep.join([helper, self.tools.apksig]), "ApkTool", "sign", keystore,
             "android", "androiddebugkey", unsigned, signed, self.min_sdk], "APK signing")

    def verify(self, apk: str, debuggable: bool = True) -> None:
        """Signature (apksig), badging (aapt2), debuggable only for debug, and that the dex holds the launcher."""
        helper = self.tools.helper_classes("ApkTool", [self.tools.apksig])
        sig = run([self.tools.java, "-cp", os.pathsep.join([helper, self.tools.apksig]), "ApkTool", "verify", apk,
                   self.min_sdk], "APK signature verification").strip()
        badging = run([self.tools.aapt2, "dump", "badging", apk], "aapt2 dump badging")
        package = re.search(r"package: name='([^']+)'", badging)
        activity = re.search(r"launchable-activity: name='([^']+)'", badging)
        if not package or package.group(1) != self.application_id:
            raise BuildError(f"APK package is {package and package.group(1)}, expected {self.application_id}")
        if not activity:
            raise BuildError("APK has no launchable activity")
        sdk = re.search(r"(?m)^(?:minSdkVersion|sdkVersion):'(\d+)'", badging)
        target = re.search(r"(?m)^targetSdkVersion:'(\d+)'", badging)
        if not sdk or sdk.group(1) != self.min_sdk or not target or target.group(1) != self.target_sdk:
            raise BuildError(f"APK SDK levels are min {sdk and sdk.group(1)} / target {target and target.group(1)}")
        if ("application-debuggable" in badging) != debuggable:
            raise BuildError(f"APK is {'not ' if debuggable else ''}debuggable, expected the opposite")
        descriptor = "L" + activity.group(1).replace(".", "/") + ";"
        with zipfile.ZipFile(apk) as z:
            dexes = [n for n in z.namelist() if re.fullmatch(r"classes\d*\.dex", n)]
            if not any(descriptor in dex_type_names(z.read(n)) for n in dexes):
                raise BuildError(f"no dex in the APK defines {descriptor}")
        size = os.path.getsize(apk)
        info(f"{sig}; package {package.group(1)}, launcher {activity.group(1)}, minSdk {self.min_sdk}, "
             f"targetSdk {self.target_sdk}, {len(dexes)} dex, {size / 1e6:.2f} MB")

    # -- tests ------------------------------------------------------------------------------------
    def test(self, name_filter: str | None, record_screenshots: bool = False, extra_jvm_args: tuple[str, ...] = ()) -> TestResult:
        """Runs the app's Robolectric tests. Screenshot tests compare with docs/images/screens/ unless
        `record_screenshots` (./build screenshots), which passes `roborazzi.test.record=true` instead. `extra_jvm_args`
        go last on the test JVM's command line (the arrival bench's `HAPTICON_BENCH_JVM_ARGS`)."""
        if not self.b.sources(self.m, "test"):
            return TestResult(self.m.path)
        self.b.compile_module(self.m, "main")
        work = os.path.join(self.out, "intermediates", "test")
        fp = fingerprint(self.b.external_classpath(self.m, "test-runtime"), self._resource_sources(), str(self.m.android))
        stamp = os.path.join(work, "resources.stamp")
        res_apk, r_jar = os.path.join(work, "resources.apk"), os.path.join(work, "R.jar")
        if not (os.path.exists(stamp) and open(stamp).read() == fp and os.path.exists(r_jar)):
            with Stage(f"test resources {self.m.path}"):
                self._link("test-runtime", work)
                with open(stamp, "w") as f:
                    f.write(fp)
        config = os.path.join(work, "config")
        os.makedirs(os.path.join(config, "com", "android", "tools"), exist_ok=True)
        assets = os.path.join(self.src, "assets")
        with open(os.path.join(config, "com", "android", "tools", "test_config.properties"), "w") as f:
            f.write(f"android_merged_manifest={os.path.join(work, 'AndroidManifest.xml')}\n"
                    f"android_resource_apk={res_apk}\n"
                    f"android_merged_assets={assets if os.path.isdir(assets) else os.path.join(work, 'assets')}\n"
                    f"android_custom_package={self.namespace}\n")
        test_classes = self.b.compile_module(self.m, "test", extra_classpath=[r_jar]).classes
        runtime = [test_classes, config, r_jar]
        runtime += [e for e in self.b.runtime_classpath(self.m, "test") if e != test_classes]
        runtime.append(self.tools.android_runtime_jar)
        roborazzi = os.path.join(self.out, "roborazzi")  # diffs and reports: build output, never committed
        mode = "record" if record_screenshots else "verify"
        jvm_args = [
            "-Drobolectric.offline=true", f"-Drobolectric.dependency.dir={self.tools.robolectric_sdk_dir}",
            "-Drobolectric.logging.enabled=false",
            # Closing a ParcelFileDescriptor (a content URI read, e.g. a photo of an invite code) goes through
            # Robolectric's FileDescriptorInterceptor, which moves FileDescriptor.fd by reflection.
            "--add-opens=java.base/java.io=ALL-UNNAMED",
            # JDK 17.0.15's C2 crashed (SIGSEGV in Node::uncast) compiling this Robolectric-instrumented method and
            # took the whole test JVM with it; this one method is interpreted instead (it is short and rarely hot).
            "-XX:CompileCommand=quiet",
            "-XX:CompileCommand=exclude,android.database.sqlite.SQLiteConnection::*applyBlockGuardPolicy",
            f"-Droborazzi.test.{mode}=true", f"-Droborazzi.output.dir={roborazzi}",
            f"-Droborazzi.compare.output.dir={roborazzi}", f"-Droborazzi.result.dir={roborazzi}/results",
            f"-Dhapticon.screens.dir={os.path.join(self.b.root, 'docs', 'images', 'screens')}", *extra_jvm_args]
        # SDK 36's framework jar is Java 21 bytecode: the classes that ask @Config(sdk = [36]) run in a second JVM on a
        # JDK 21+, everything else (screenshots included) in the build's JDK as before.
        rest = self.b.run_junit(self.m, test_classes, runtime, name_filter, jvm_args=[*jvm_args, "-Dhapticon.test.sdk36=without"])
        if not self._asks_for_sdk36():
            return rest
        # Robolectric's SDK 36 setup (ApplicationSharedMemory) sets a FileDescriptor's fd through
        # jdk.internal.access.SharedSecrets (sandbox AndroidInterceptors.FileDescriptorInterceptor), which the JDK
        # keeps closed unless opened; its native runtime loads with native access.
        opens = [f"--add-opens=java.base/{p}=ALL-UNNAMED" for p in ("jdk.internal.access", "java.io", "java.lang", "java.util")]
        newer = self.b.run_junit(self.m, test_classes, runtime, name_filter,
                                 jvm_args=[*opens, "--enable-native-access=ALL-UNNAMED", *jvm_args, "-Dhapticon.test.sdk36=only"],
                                 java=java_for_sdk36(self.tools.java_home, fetch=lambda: fetch_java_runtime(self.tools.cache)),
                                 label=" sdk36")
        return TestResult(self.m.path, rest.passed + newer.passed, rest.failed + newer.failed, rest.skipped + newer.skipped,
                          rest.crashed or newer.crashed)

    def _asks_for_sdk36(self) -> bool:
        """Whether a test source names `sdk = [36]` (or later) in a Robolectric @Config."""
        for path in self.b.sources(self.m, "test"):
            with open(path, encoding="utf-8") as f:
                if re.search(r"sdk\s*=\s*\[[^\]]*\b(3[6-9]|[4-9]\d)\b", f.read()):
                    return True
        return False


def _each(option: str, values: list[str]) -> list[str]:
    return [a for v in values for a in (option, v)]


def _dex_order(path: str) -> int:
    m = re.fullmatch(r"classes(\d*)\.dex", os.path.basename(path))
    if not m:
        raise BuildError(f"unexpected D8 output {path}")
    return int(m.group(1) or 1)


def _jar_directory(directory: str, jar: str) -> None:
    with zipfile.ZipFile(jar, "w", zipfile.ZIP_DEFLATED) as z:
        _add_tree(z, directory)


def _add_tree(z: zipfile.ZipFile, entry: str, classes_only: bool = False) -> None:
    for name, read in _iter_files(entry):
        if not classes_only or name.endswith(".class"):
            z.writestr(name, read())


def _iter_files(entry: str):
    if os.path.isdir(entry):
        for root, _d, files in sorted(os.walk(entry)):
            for f in sorted(files):
                p = os.path.join(root, f)
                yield os.path.relpath(p, entry).replace(os.sep, "/"), (lambda p=p: open(p, "rb").read())
    elif entry.endswith(".jar") and os.path.exists(entry):
        with zipfile.ZipFile(entry) as z:
            for n in z.namelist():
                yield n, (lambda n=n: z.read(n))


def _uleb128(data: bytes, pos: int) -> tuple[int, int]:
    result = shift = 0
    while True:
        b = data[pos]
        pos += 1
        result |= (b & 0x7F) << shift
        if b < 0x80:
            return result, pos
        shift += 7


def defined_twice(type_sets: list[set[str]]) -> set[str]:
    """The types that more than one of `type_sets` (each dex file's [dex_type_names]) defines."""
    seen, twice = set(), set()
    for types in type_sets:
        twice |= seen & types
        seen |= types
    return twice


def dex_type_names(dex: bytes) -> set[str]:
    """Type descriptors (e.g. `Lorg/x/MainActivity;`) of the classes a dex file defines: each class_def's
    class_idx, without reading the classes' members ([dex_classes] does)."""
    d = _Dex(dex)
    return {d.type_name(struct.unpack_from("<I", dex, d.class_defs_off + 32 * c)[0]) for c in range(d.class_defs_size)}


@dataclass(frozen=True)
class DexClass:
    """A class a dex file defines: its superclass descriptor (None for java.lang.Object) and the members its
    class_data_item declares — methods as name + descriptor (`<init>()V`), fields as name + type
    (`producerIndex:J`)."""
    superclass: str | None
    methods: frozenset[str]
    fields: frozenset[str]


class _Dex:
    """The id tables of a dex file (header, string_ids, type_ids, proto_ids, field_ids, method_ids, class_defs)
    and its classes' class_data_items, as the DEX format defines them:
    https://source.android.com/docs/core/runtime/dex-format"""

    def __init__(self, dex: bytes):
        if dex[:4] != b"dex\n" or len(dex) < 0x70:
            raise BuildError("not a dex file")
        self.dex = dex
        (_string_ids_size, self.string_ids_off, _type_ids_size, self.type_ids_off, _proto_ids_size, self.proto_ids_off,
         _field_ids_size, self.field_ids_off, _method_ids_size, self.method_ids_off, self.class_defs_size,
         self.class_defs_off) = struct.unpack_from("<12I", dex, 0x38)
        self._strings: dict[int, str] = {}

    def string(self, i: int) -> str:
        if i not in self._strings:
            off = struct.unpack_from("<I", self.dex, self.string_ids_off + 4 * i)[0]
            _length, start = _uleb128(self.dex, off)
            # MUTF-8; the names looked at here are ASCII
            self._strings[i] = self.dex[start:self.dex.index(b"\0", start)].decode("utf-8", "replace")
        return self._strings[i]

    def type_name(self, i: int) -> str:
        return self.string(struct.unpack_from("<I", self.dex, self.type_ids_off + 4 * i)[0])

    def proto(self, i: int) -> str:
        _shorty, return_idx, parameters_off = struct.unpack_from("<III", self.dex, self.proto_ids_off + 12 * i)
        params = []
        if parameters_off:
            size = struct.unpack_from("<I", self.dex, parameters_off)[0]
            params = [self.type_name(t) for t in struct.unpack_from(f"<{size}H", self.dex, parameters_off + 4)]
        return "(" + "".join(params) + ")" + self.type_name(return_idx)

    def field(self, i: int) -> str:
        _class_idx, type_idx, name_idx = struct.unpack_from("<HHI", self.dex, self.field_ids_off + 8 * i)
        return f"{self.string(name_idx)}:{self.type_name(type_idx)}"

    def method(self, i: int) -> str:
        _class_idx, proto_idx, name_idx = struct.unpack_from("<HHI", self.dex, self.method_ids_off + 8 * i)
        return self.string(name_idx) + self.proto(proto_idx)

    def method_holder(self, i: int) -> str:
        return self.type_name(struct.unpack_from("<H", self.dex, self.method_ids_off + 8 * i)[0])

    def classes(self):
        """Each class_def as (descriptor, superclass descriptor or None, fields, methods as (name+proto,
        code_off))): class_data_item is four uleb128 counts, then field_idx_diff/access_flags and
        method_idx_diff/access_flags/code_off per member, the index a running sum within each list."""
        dex = self.dex
        for c in range(self.class_defs_size):
            class_idx, _flags, superclass_idx, _interfaces, _source, _annotations, class_data_off, _static = \
                struct.unpack_from("<8I", dex, self.class_defs_off + 32 * c)
            fields, methods = set(), []
            if class_data_off:
                pos = class_data_off
                counts = []
                for _ in range(4):
                    n, pos = _uleb128(dex, pos)
                    counts.append(n)
                for k, count in enumerate(counts):
                    index = 0
                    for _ in range(count):
                        diff, pos = _uleb128(dex, pos)
                        index += diff
                        _access, pos = _uleb128(dex, pos)
                        if k < 2:  # static_fields, instance_fields
                            fields.add(self.field(index))
                        else:  # direct_methods, virtual_methods (then code_off)
                            code, pos = _uleb128(dex, pos)
                            methods.append((index, code))
            yield (self.type_name(class_idx), None if superclass_idx == 0xFFFFFFFF else self.type_name(superclass_idx),
                   fields, methods)


def dex_classes(dex: bytes) -> dict[str, DexClass]:
    """Every class a dex file defines, by descriptor, with its declared methods and fields ([_Dex])."""
    d = _Dex(dex)
    return {name: DexClass(superclass, frozenset(d.method(m) for m, _code in methods), frozenset(fields))
            for name, superclass, fields, methods in d.classes()}


# Dalvik instructions by opcode: (size in 16-bit code units, how it writes a register) — "": none,
# "a4": vA in the low nibble of byte 1, "a8": vA is byte 1, "a16": vA is code unit 1 (format 32x); a "w" suffix
# marks a wide (register pair) result. From the DEX bytecode and instruction-format tables:
# https://source.android.com/docs/core/runtime/dalvik-bytecode, …/instruction-formats
def _dalvik_table() -> list[tuple[int, str]]:
    t = [(1, "")] * 256  # unused opcodes are 10x
    def put(first, last, size, writes=""):
        for op in range(first, last + 1):
            t[op] = (size, writes)
    put(0x01, 0x01, 1, "a4"); put(0x02, 0x02, 2, "a8"); put(0x03, 0x03, 3, "a16")          # move
    put(0x04, 0x04, 1, "a4w"); put(0x05, 0x05, 2, "a8w"); put(0x06, 0x06, 3, "a16w")       # move-wide
    put(0x07, 0x07, 1, "a4"); put(0x08, 0x08, 2, "a8"); put(0x09, 0x09, 3, "a16")          # move-object
    put(0x0a, 0x0a, 1, "a8"); put(0x0b, 0x0b, 1, "a8w"); put(0x0c, 0x0d, 1, "a8")         # move-result*, move-exception
    put(0x0f, 0x11, 1)                                                                      # return
    put(0x12, 0x12, 1, "a4"); put(0x13, 0x13, 2, "a8"); put(0x14, 0x14, 3, "a8"); put(0x15, 0x15, 2, "a8")
    put(0x16, 0x16, 2, "a8w"); put(0x17, 0x17, 3, "a8w"); put(0x18, 0x18, 5, "a8w"); put(0x19, 0x19, 2, "a8w")
    put(0x1a, 0x1a, 2, "a8"); put(0x1b, 0x1b, 3, "a8"); put(0x1c, 0x1c, 2, "a8")          # const-string(/jumbo), -class
    put(0x1d, 0x1e, 1); put(0x1f, 0x1f, 2); put(0x20, 0x20, 2, "a4"); put(0x21, 0x21, 1, "a4")
    put(0x22, 0x22, 2, "a8"); put(0x23, 0x23, 2, "a4"); put(0x24, 0x26, 3); put(0x27, 0x28, 1)
    put(0x29, 0x29, 2); put(0x2a, 0x2c, 3); put(0x2d, 0x31, 2, "a8")                       # goto/32, switches, cmp
    put(0x32, 0x3d, 2)                                                                      # if-*
    put(0x44, 0x4a, 2, "a8"); put(0x45, 0x45, 2, "a8w"); put(0x4b, 0x51, 2)                # aget, aput
    put(0x52, 0x58, 2, "a4"); put(0x53, 0x53, 2, "a4w"); put(0x59, 0x5f, 2)                # iget, iput
    put(0x60, 0x66, 2, "a8"); put(0x61, 0x61, 2, "a8w"); put(0x67, 0x6d, 2)                # sget, sput
    put(0x6e, 0x72, 3); put(0x74, 0x78, 3)                                                  # invoke-*, /range
    put(0x7b, 0x8f, 1, "a4")                                                                # unops
    for op in (0x7d, 0x7e, 0x80, 0x81, 0x83, 0x86, 0x88, 0x89, 0x8b):
        t[op] = (1, "a4w")
    put(0x90, 0xaf, 2, "a8"); put(0x9b, 0xa5, 2, "a8w"); put(0xab, 0xaf, 2, "a8w")        # binops
    put(0xb0, 0xcf, 1, "a4"); put(0xbb, 0xc5, 1, "a4w"); put(0xcb, 0xcf, 1, "a4w")        # binop/2addr
    put(0xd0, 0xd7, 2, "a4"); put(0xd8, 0xe2, 2, "a8")                                    # lit16, lit8
    put(0xfa, 0xfb, 4); put(0xfc, 0xfd, 3); put(0xfe, 0xff, 2, "a8")                      # polymorphic, custom
    return t


_DALVIK = _dalvik_table()
# Library methods that find a field by a name R8 can see, as (holder, name + descriptor): the field updaters'
# newUpdater and Class.getDeclaredField/getField. R8 recognises exactly these with constant arguments
# (r8 9.x, com.android.tools.r8.shaking.reflectiveidentification.EnqueuerReflectiveIdentificationAnalysis
# .scanInvoke: an implicit -identifiernamestring, then naming/IdentifierNameStringMarker rewrites the
# string to the field's new name).
DEX_FIELD_LOOKUPS = {
    ("Ljava/util/concurrent/atomic/AtomicIntegerFieldUpdater;",
     "newUpdater(Ljava/lang/Class;Ljava/lang/String;)Ljava/util/concurrent/atomic/AtomicIntegerFieldUpdater;"),
    ("Ljava/util/concurrent/atomic/AtomicLongFieldUpdater;",
     "newUpdater(Ljava/lang/Class;Ljava/lang/String;)Ljava/util/concurrent/atomic/AtomicLongFieldUpdater;"),
    ("Ljava/util/concurrent/atomic/AtomicReferenceFieldUpdater;",
     "newUpdater(Ljava/lang/Class;Ljava/lang/Class;Ljava/lang/String;)"
     "Ljava/util/concurrent/atomic/AtomicReferenceFieldUpdater;"),
    ("Ljava/lang/Class;", "getDeclaredField(Ljava/lang/String;)Ljava/lang/reflect/Field;"),
    ("Ljava/lang/Class;", "getField(Ljava/lang/String;)Ljava/lang/reflect/Field;"),
}


def dex_field_lookups(dex: bytes) -> set[tuple[str, str]]:
    """(class descriptor, field name) pairs the dex's code looks up by name: a [DEX_FIELD_LOOKUPS] call whose
    class and name arguments hold a `const-class` and a `const-string` (the class the first argument, or the
    receiver of getDeclaredField; the name the last). Registers are followed through each method's
    instructions in order (straight-line code, which is how javac/kotlinc/R8 emit these calls); any other write
    to a register forgets its constant, so a lookup whose arguments are not plain constants is not reported."""
    return _dex_code_constants(dex)[0]


def dex_code_strings(dex: bytes) -> set[str]:
    """Every string the dex's code loads with const-string(/jumbo): a name that is not among them cannot be
    looked up by any constant in this dex."""
    return _dex_code_constants(dex)[1]


def _dex_code_constants(dex: bytes) -> tuple[set[tuple[str, str]], set[str]]:
    d = _Dex(dex)
    dex_ = d.dex
    lookup_methods: dict[int, bool] = {}
    found, strings = set(), set()
    for _name, _super, _fields, methods in d.classes():
        for _m, code in methods:
            if not code:
                continue
            insns_size = struct.unpack_from("<I", dex_, code + 12)[0]
            pos, end = code + 16, code + 16 + 2 * insns_size
            regs: dict[int, tuple[str, str]] = {}  # register → ("class", descriptor) or ("string", text)
            while pos < end:
                op, b1 = dex_[pos], dex_[pos + 1]
                if op == 0x00 and b1 in (1, 2, 3):  # switch and array-data payloads (pseudo-instructions)
                    if b1 == 1:
                        size = 4 + 2 * struct.unpack_from("<H", dex_, pos + 2)[0]
                    elif b1 == 2:
                        size = 2 + 4 * struct.unpack_from("<H", dex_, pos + 2)[0]
                    else:
                        width, count = struct.unpack_from("<HI", dex_, pos + 2)
                        size = 4 + (width * count + 1) // 2
                    pos += 2 * size
                    continue
                size, writes = _DALVIK[op]
                if op in (0x1a, 0x1b):
                    idx = struct.unpack_from("<H" if op == 0x1a else "<I", dex_, pos + 2)[0]
                    regs[b1] = ("string", d.string(idx))
                    strings.add(regs[b1][1])
                elif op == 0x1c:
                    regs[b1] = ("class", d.type_name(struct.unpack_from("<H", dex_, pos + 2)[0]))
                elif op in (0x07, 0x08, 0x09):  # move-object keeps a constant
                    a, b = ((b1 & 0xF, b1 >> 4) if op == 0x07 else (b1, struct.unpack_from("<H", dex_, pos + 2)[0])
                            if op == 0x08 else struct.unpack_from("<HH", dex_, pos + 2))
                    if b in regs:
                        regs[a] = regs[b]
                    else:
                        regs.pop(a, None)
                elif op in (0x6e, 0x71, 0x74, 0x77):  # invoke-virtual, invoke-static (and /range)
                    midx = struct.unpack_from("<H", dex_, pos + 2)[0]
                    if midx not in lookup_methods:
                        lookup_methods[midx] = (d.method_holder(midx), d.method(midx)) in DEX_FIELD_LOOKUPS
                    if lookup_methods[midx]:
                        if op in (0x6e, 0x71):
                            unit = struct.unpack_from("<H", dex_, pos + 4)[0]
                            args = [unit & 0xF, (unit >> 4) & 0xF, (unit >> 8) & 0xF, (unit >> 12) & 0xF, b1 & 0xF]
                            args = args[:b1 >> 4]
                        else:
                            first = struct.unpack_from("<H", dex_, pos + 4)[0]
                            args = list(range(first, first + b1))
                        cls, name = regs.get(args[0]), regs.get(args[-1])
                        if cls and name and cls[0] == "class" and name[0] == "string":
                            found.add((cls[1], name[1]))
                elif writes:
                    a = b1 & 0xF if writes.startswith("a4") else b1 if writes.startswith("a8") else \
                        struct.unpack_from("<H", dex_, pos + 2)[0]
                    regs.pop(a, None)
                    if writes.endswith("w"):
                        regs.pop(a + 1, None)
                pos += 2 * size
    return found, strings


@dataclass(frozen=True)
class Signing:
    """A release signing key: `--keystore`/`--key-alias` or HAPTICON_RELEASE_KEYSTORE/_KEY_ALIAS, and the
    passwords only from the environment (HAPTICON_RELEASE_STORE_PASSWORD, HAPTICON_RELEASE_KEY_PASSWORD,
    the latter defaulting to the store password), so they never appear in a command line."""
    keystore: str
    alias: str
    store_password: str
    key_password: str

    @staticmethod
    def from_args(args: list[str], env=os.environ) -> "Signing":
        def option(name: str, variable: str) -> str | None:
            if name in args:
                i = args.index(name)
                if i + 1 >= len(args):
                    raise BuildError(f"{name} needs a value")
                return args[i + 1]
            return env.get(variable)
        keystore = option("--keystore", "HAPTICON_RELEASE_KEYSTORE")
        alias = option("--key-alias", "HAPTICON_RELEASE_KEY_ALIAS")
        store_password = env.get("HAPTICON_RELEASE_STORE_PASSWORD")
        if not keystore or not alias or not store_password:
            raise BuildError("a release APK needs a signing key: --keystore PATH --key-alias ALIAS (or "
                             "HAPTICON_RELEASE_KEYSTORE, HAPTICON_RELEASE_KEY_ALIAS) and HAPTICON_RELEASE_STORE_PASSWORD "
                             "(and HAPTICON_RELEASE_KEY_PASSWORD if the key's differs); see docs/release.md")
        if not os.path.isfile(keystore):
            raise BuildError(f"keystore {keystore} not found")
        return Signing(keystore, alias, store_password, env.get("HAPTICON_RELEASE_KEY_PASSWORD") or store_password)


# Classes the app reaches by name at run time, which R8 must keep under their own names (app/proguard-rules.pro):
# the MQTT client's implementation and netty's channel, the player, Room's runtime lookup. (MqttClient, an
# interface whose static builder() R8 moves, is rightly gone from the output.)
REFLECTIVE_CLASSES = [
    "com.hivemq.client.internal.mqtt.MqttRxClient",
    "io.netty.channel.socket.nio.NioSocketChannel",
    "androidx.media3.exoplayer.ExoPlayer",
    "androidx.media3.exoplayer.ExoPlayerImpl",
    "androidx.room.RoomDatabase",
]

# Members reached without a direct call that R8 could see, as (class, method name + descriptor). netty's
# NioSocketChannel is made through a ChannelFactory (HiveMQ 1.4.2's NettyEventLoopProvider passes
# `NioSocketChannel::new`; `Bootstrap.channel(NioSocketChannel.class)` would use ReflectiveChannelFactory's
# getConstructor()), kept by `-keep class io.netty.channel.socket.nio.NioSocketChannel { <init>(); }`.
# Room's `<init>()` on each database `_Impl` is added by [required_members] from the program itself.
REFLECTIVE_MEMBERS = [
    ("io.netty.channel.socket.nio.NioSocketChannel", "<init>()V"),
]

# Calls that find a field by its name in a string constant: `AtomicXFieldUpdater.newUpdater(X.class, "f")`
# (netty, RxJava, coroutines' atomicfu), JCTools' `UnsafeAccess.fieldOffset(X.class, "f")` (also shaded into
# netty) and netty's `ReferenceCountUpdater.getUnsafeOffset(X.class, "f")`, `X.class.getDeclaredField("f")`.
# HiveMQ's Android guide names these as what R8 must not rename or remove; app/proguard-rules.pro and the
# libraries' own rules (coroutines: `volatile <fields>`) keep them.
# The packages whose by-name fields the check requires: netty, JCTools, coroutines and RxJava, kept by rules, and
# androidx.concurrent (AbstractResolvableFuture), the Kotlin standard library (SafePublicationLazyImpl._value,
# SafeContinuation.result) and Guava's futures, whose constant newUpdater names R8 rewrites itself when it renames
# the field ([DEX_FIELD_LOOKUPS]; checked in the release dex on 2026-11-26, docs/release.md). The rest of the scan
# finds only framework classes (android.*, java.*), which are not in the dex.
FIELD_LOOKUP_PACKAGES = ("io.netty.", "org.jctools.", "kotlinx.coroutines.", "io.reactivex.", "androidx.concurrent.",
                         "kotlin.", "com.google.common.util.concurrent.")
FIELD_LOOKUPS = {"newUpdater", "fieldOffset", "getUnsafeOffset", "getDeclaredField",
                 "newAtomicIntegerFieldUpdater", "newAtomicLongFieldUpdater", "newAtomicReferenceFieldUpdater"}


def _class_file(data: bytes) -> tuple[str, str | None, dict[int, tuple]]:
    """A class file's name, superclass (internal names, `a/b/C`) and constant pool (JVMS §4.1, §4.4)."""
    if data[:4] != b"\xca\xfe\xba\xbe":
        raise BuildError("not a class file")
    count = struct.unpack_from(">H", data, 8)[0]
    pool: dict[int, tuple] = {}
    pos, i = 10, 1
    while i < count:
        tag = data[pos]
        if tag == 1:
            length = struct.unpack_from(">H", data, pos + 1)[0]
            pool[i] = (1, data[pos + 3:pos + 3 + length].decode("utf-8", "replace"))
            pos += 3 + length
        elif tag in (7, 8, 16, 19, 20):
            pool[i] = (tag, struct.unpack_from(">H", data, pos + 1)[0])
            pos += 3
        elif tag in (9, 10, 11, 12, 17, 18):
            pool[i] = (tag, *struct.unpack_from(">HH", data, pos + 1))
            pos += 5
        elif tag == 15:
            pos += 4
        elif tag in (3, 4):
            pos += 5
        elif tag in (5, 6):
            pos += 9
            i += 1  # longs and doubles take two slots
        else:
            raise BuildError(f"unknown constant pool tag {tag}")
        i += 1
    this_class, super_class = struct.unpack_from(">HH", data, pos + 2)
    utf = lambda k: pool[k][1]
    return utf(pool[this_class][1]), utf(pool[super_class][1]) if super_class else None, pool


JDK_PREFIXES = ("Ljava/", "Ljavax/", "Ljdk/", "Lsun/", "Lcom/sun/")


def app_class_references(program_jar: str) -> set[str]:
    """Descriptors (`La/b/C;`) of every class the classes in `program_jar` name in their constant pools
    (CONSTANT_Class: what they instantiate, call, cast to or load as a literal), array types by their element
    class; what the app cannot run without."""
    names = set()
    with zipfile.ZipFile(program_jar) as z:
        for n in z.namelist():
            if n.endswith(".class") and not n.startswith("META-INF/"):
                _name, _super, pool = _class_file(z.read(n))
                for tag, *value in pool.values():
                    if tag == 7:
                        name = pool[value[0]][1].lstrip("[")
                        if name.startswith("L") and name.endswith(";"):
                            names.add(name)
                        elif len(name) > 1:  # a plain internal name; `I`, `J`, … are a primitive array's element
                            names.add("L" + name + ";")
    return names


def field_lookups(data: bytes) -> set[tuple[str, str]]:
    """(class, field) pairs a class file looks up by name: a [FIELD_LOOKUPS] call whose arguments are pushed by
    `ldc X.class`, … `ldc "field"` right before it (what javac and kotlinc emit for constant arguments)."""
    _name, _super, pool = _class_file(data)

    def constant(pos: int) -> tuple[int, tuple] | None:  # the ldc/ldc_w ending right before `pos`, if any
        if pos >= 2 and data[pos - 2] == 0x12 and pool.get(data[pos - 1], (0,))[0] in (7, 8):
            return pos - 2, pool[data[pos - 1]]
        if pos >= 3 and data[pos - 3] == 0x13:
            k = struct.unpack_from(">H", data, pos - 2)[0]
            if pool.get(k, (0,))[0] in (7, 8):
                return pos - 3, pool[k]
        return None

    found = set()
    for m in re.finditer(rb"[\xb6\xb8]", data):  # invokevirtual, invokestatic
        p = m.start()
        if p + 3 > len(data):
            continue
        ref = pool.get(struct.unpack_from(">H", data, p + 1)[0])
        if not ref or ref[0] not in (10, 11):
            continue
        name_and_type = pool.get(ref[2])
        if not name_and_type or name_and_type[0] != 12 or pool[name_and_type[1]][1] not in FIELD_LOOKUPS:
            continue
        pushed, pos = [], p
        while (c := constant(pos)) is not None:
            pos, entry = c
            pushed.insert(0, entry)
        strings = [pool[e[1]][1] for e in pushed if e[0] == 8]
        classes = [pool[e[1]][1] for e in pushed if e[0] == 7]
        if strings and classes and classes[0].replace("/", ".").startswith(FIELD_LOOKUP_PACKAGES):
            found.add((classes[0].replace("/", "."), strings[-1]))
    return found


def required_classes(program_jar: str, manifest: str) -> list[str]:
    """What the minified app must still define by name: every manifest component, every Room-generated
    `_Impl` (Room finds a database's implementation by name, and a DAO's through it), and
    [REFLECTIVE_CLASSES]."""
    names = set(REFLECTIVE_CLASSES)
    with zipfile.ZipFile(program_jar) as z:
        for n in z.namelist():
            if n.endswith("_Impl.class") and "$" not in n:
                names.add(n.removesuffix(".class").replace("/", "."))
    text = open(manifest).read() if os.path.exists(manifest) else ""
    package = re.search(r'package="([^"]+)"', text)
    for m in re.finditer(r'<(?:activity|service|receiver|provider|application)\b[^>]*?android:name="([^"]+)"', text, re.S):
        name = m.group(1)
        if name.startswith(".") and package:
            name = package.group(1) + name
        names.add(name)
    return sorted(names)


def required_members(program_jar: str, library_jars: list[str], cache: str | None = None) -> list[tuple[str, str]]:
    """Members the minified app must still define under their own names, as (class, member): `<init>()V` of
    each Room database `_Impl` (room-runtime 2.8's `androidx.room.util.KClassUtil.findAndInstantiateDatabaseImpl`
    does `Class.forName(<Database> + "_Impl").getDeclaredConstructor().newInstance()`; room-runtime's own rule `-keep class * extends androidx.room.RoomDatabase { void <init>(); }`;
    the DAO and auto-migration `_Impl`s are constructed directly by the database's generated code, so only
    their names are checked), [REFLECTIVE_MEMBERS], and every field found by name ([field_lookups]) in the
    program and its libraries, as its bare name (any type). A library jar's lookups are kept in `cache`
    (a directory), by the jar's path and size, as Maven artifacts do not change under one name."""
    members = set(REFLECTIVE_MEMBERS)
    supers: dict[str, str | None] = {}
    with zipfile.ZipFile(program_jar) as z:
        for n in z.namelist():
            if n.endswith(".class") and not n.startswith("META-INF/"):
                data = z.read(n)
                name, superclass, _pool = _class_file(data)
                supers[name] = superclass
                if any(f.encode() in data for f in FIELD_LOOKUPS):
                    members.update(field_lookups(data))
    for jar in library_jars:
        members.update(_jar_field_lookups(jar, cache))
    for name in supers:
        s = supers[name]
        while s in supers:
            s = supers[s]
        if name.endswith("_Impl") and s == "androidx/room/RoomDatabase":
            members.add((name.replace("/", "."), "<init>()V"))
    return sorted(members)


def _jar_field_lookups(jar: str, cache: str | None) -> set[tuple[str, str]]:
    scope = ",".join(FIELD_LOOKUP_PACKAGES)
    key = hashlib.sha1(f"{os.path.abspath(jar)}:{os.path.getsize(jar)}:{scope}".encode()).hexdigest()[:16]
    cached = os.path.join(cache, key + ".json") if cache else None
    if cached and os.path.exists(cached):
        with open(cached) as f:
            return {tuple(pair) for pair in json.load(f)}
    found = set()
    with zipfile.ZipFile(jar) as z:
        for n in z.namelist():
            if n.endswith(".class") and not n.startswith("META-INF/"):
                data = z.read(n)
                if any(f.encode() in data for f in FIELD_LOOKUPS):
                    found.update(field_lookups(data))
    if cached:
        os.makedirs(cache, exist_ok=True)
        with open(cached, "w") as f:
            json.dump(sorted(found), f)
    return found


def read_mapping(path: str | None) -> dict[str, str]:
    """R8's class renames from its mapping file (`original.Name -> new.Name:` lines); {} without one."""
    if not path or not os.path.exists(path):
        return {}
    with open(path, encoding="utf-8") as f:
        return dict(re.findall(r"(?m)^(\S+) -> (\S+):$", f.read()))


def read_field_mapping(path: str | None) -> dict[tuple[str, str], str]:
    """R8's field renames from its mapping file, as (original class, original field) → new name: the
    `    type name -> new` lines under each `original.Class -> new.Class:` line (methods have a `(`); {} without
    one. https://r8.googlesource.com/r8/+/refs/heads/main/doc/retrace.md describes the format."""
    if not path or not os.path.exists(path):
        return {}
    fields, cls = {}, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if m := re.match(r"(\S+) -> (\S+):$", line):
                cls = m.group(1)
            elif cls and (m := re.match(r"    (\S+) ([^\s(]+) -> (\S+)$", line)):
                fields[(cls, m.group(2))] = m.group(3)
    return fields


def smoke_check(dex_files: list[str], required: list[str], members: list[tuple[str, str]] = (),
                mapping: dict[str, str] | None = None,
                field_mapping: dict[tuple[str, str], str] | None = None) -> tuple[int, int, int]:
    """Fails unless every class in `required` is defined, under its own name, in `dex_files`, and every member
    in `members` ((class, `name(params)return`) for a method, (class, `name`) for a field) is declared by that
    class — under the name R8 gave the class in `mapping`, for a class it renamed. A method must keep its own
    name; so must a field, unless R8 renamed it (`field_mapping`) and rewrote its lookups too: the R8 output
    then calls a field updater's newUpdater or Class.getDeclaredField/getField with the class and the field's
    new name as constants ([dex_field_lookups]; R8 9.x does this itself for constant arguments, see
    [DEX_FIELD_LOOKUPS]). That is what a missing keep rule breaks: R8 removes or renames a class or member
    reached only by reflection. A member whose class R8 removed is not required (its lookups went with it),
    unless the class itself is in `required`; nor is a field R8 removed when the code no longer loads its name
    as a string constant ([dex_code_strings]): no lookup of it is left. Returns the numbers of classes and members checked, and of the
    fields among them found renamed with their lookups rewritten."""
    mapping = mapping or {}
    field_mapping = field_mapping or {}
    defined: dict[str, DexClass] = {}
    dex_data = []
    for d in dex_files:
        with open(d, "rb") as f:
            dex_data.append(f.read())
        defined.update(dex_classes(dex_data[-1]))
    descriptor = lambda n: "L" + n.replace(".", "/") + ";"
    missing = [n for n in required if descriptor(n) not in defined]
    if missing:
        raise BuildError("the R8 output lacks classes reached by name (a missing keep rule in "
                         f"app/proguard-rules.pro?): {', '.join(missing)}")
    code: tuple[set, set] | None = None  # lookups and strings, read from the code only when a field is not found

    def code_constants() -> tuple[set[tuple[str, str]], set[str]]:
        nonlocal code
        if code is None:
            parts = [_dex_code_constants(d) for d in dex_data]
            code = set().union(*(p[0] for p in parts)), set().union(*(p[1] for p in parts))
        return code

    lost, checked, rewritten = [], 0, 0
    for cls, member in members:
        target = descriptor(mapping.get(cls, cls))
        found = defined.get(target)
        if found is None:
            continue
        checked += 1
        renamed = f" (renamed {mapping[cls]})" if mapping.get(cls, cls) != cls else ""
        if "(" in member:
            if member not in found.methods:
                lost.append(f"{cls}{renamed}.{member}")
            continue
        names = {f.split(":", 1)[0] for f in found.fields}
        if member in names:
            continue
        new = field_mapping.get((cls, member))
        if new in names:
            if (target, new) in code_constants()[0]:
                rewritten += 1
                continue
            lost.append(f"{cls}{renamed}.{member} (renamed {new}, which no lookup in the R8 output names)")
        elif member in code_constants()[1]:
            lost.append(f"{cls}{renamed}.{member}")
        else:
            # R8 removed the field and no code still holds its name: every lookup of it went with it (e.g. the
            # static updater of a class whose updating methods are unreachable). Nothing can miss it.
            checked -= 1
    if lost:
        raise BuildError(f"the R8 output lacks {len(lost)} members reached by name (a missing keep rule in "
                         f"app/proguard-rules.pro?): {', '.join(lost[:8])}{' …' if len(lost) > 8 else ''}")
    return len(required), checked, rewritten
