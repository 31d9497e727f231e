"""Dependency resolution with Gradle's semantics, from Gradle Module Metadata (`.module`) files.

Plain Maven resolution of AndroidX fails (BOM entries typed jar, exact version ranges, KMP root
modules holding only metadata, nearest-wins picking lower versions than Gradle). So, like Gradle:
the highest requested version wins, `available-at` redirects are followed to the platform variant,
dependency constraints (AndroidX atomic groups, BOMs) raise versions of modules in the graph, and
POMs are read only where a library publishes no module metadata.
"""
from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

from .errors import BuildError
from .maven import Repository

_QUALIFIERS = {"dev": 0, "snapshot": 0, "alpha": 1, "a": 1, "beta": 2, "b": 2,
               "milestone": 3, "m": 3, "rc": 4, "cr": 4}


def version_key(v: str):
    """Ordering close to Gradle's: numeric parts numerically, alpha < beta < rc < release."""
    key = []
    for part in re.findall(r"\d+|[a-zA-Z]+", v):
        if part.isdigit():
            key.append((2, int(part), ""))
        else:
            rank = _QUALIFIERS.get(part.lower())
            key.append((0, rank, "") if rank is not None else (1, 0, part.lower()))
    key.append((1, 0, ""))
    return key


def highest(versions) -> str:
    return max(versions, key=version_key)


def concrete_version(spec) -> str | None:
    if isinstance(spec, dict):
        spec = spec.get("strictly") or spec.get("requires") or spec.get("prefers")
    if not spec:
        return None
    spec = spec.strip()
    m = re.fullmatch(r"\[([^,\]]+)\]", spec) or re.fullmatch(r"\[([^,\]]+),\s*\1\]", spec)
    if m:
        return m.group(1)
    m = re.fullmatch(r"[\[(]([^,]*),([^\])]*)[\])]", spec)
    if m:  # a range: its lower bound, which constraints raise as needed
        return m.group(1).strip() or m.group(2).strip()
    return spec


@dataclass
class Node:
    files: list[str] = field(default_factory=list)   # paths relative to the repository root
    deps: list[tuple[str, str, str | None, frozenset]] = field(default_factory=list)
    constraints: list[tuple[str, str, str]] = field(default_factory=list)
    redirect: tuple[str, str, str] | None = None
    source: str = "module"


@dataclass
class Artifact:
    group: str
    name: str
    version: str
    files: list[str]

    @property
    def coordinate(self) -> str:
        return f"{self.group}:{self.name}:{self.version}"


class Resolver:
    """Resolves runtime classpaths for the `android` or `jvm` platform."""

    def __init__(self, repo: Repository, platform: str):
        if platform not in ("android", "jvm"):
            raise ValueError(platform)
        self.repo = repo
        self.platform = platform
        self._nodes: dict[tuple, Node] = {}
        self._poms: dict[tuple, dict | None] = {}

    # -- metadata ---------------------------------------------------------------------------------
    def _variant(self, module: dict):
        platform_rank = {"androidJvm": 3, "jvm": 2, None: 1} if self.platform == "android" else {"jvm": 3, None: 2}
        env_rank = ({"android": 2, None: 1, "standard-jvm": 1} if self.platform == "android"
                    else {"standard-jvm": 2, None: 1, "android": 0})
        best, best_score = None, -1
        for v in module.get("variants", []):
            attrs = v.get("attributes", {})
            if attrs.get("org.gradle.usage") != "java-runtime":
                continue
            category = attrs.get("org.gradle.category", "library")
            if category not in ("library", "platform"):
                continue
            kotlin_platform = attrs.get("org.jetbrains.kotlin.platform.type")
            if kotlin_platform not in platform_rank:
                continue
            if attrs.get("com.android.build.api.attributes.BuildTypeAttr") not in (None, "release"):
                continue
            score = (platform_rank[kotlin_platform] * 10 + env_rank.get(attrs.get("org.gradle.jvm.environment"), 0)
                     + (100 if category == "library" else 0))
            if score > best_score:
                best, best_score = v, score
        return best

    def _pom(self, g: str, a: str, v: str) -> dict | None:
        key = (g, a, v)
        if key in self._poms:
            return self._poms[key]
        data = self.repo.read(Repository.relative(g, a, v, f"{a}-{v}.pom"))
        if data is None:
            self._poms[key] = None
            return None
        root = ET.fromstring(data)
        ns = root.tag[1:].split("}")[0] if root.tag.startswith("{") else ""
        q = (lambda p: "/".join(f"{{{ns}}}{x}" for x in p.split("/"))) if ns else (lambda p: p)

        def text(el, p):
            x = el.find(q(p))
            return x.text.strip() if x is not None and x.text else None

        props, managed, managed_scopes = {}, {}, {}
        pg, pa, pv = text(root, "parent/groupId"), text(root, "parent/artifactId"), text(root, "parent/version")
        if pg:
            parent = self._pom(pg, pa, pv)
            if parent:
                props.update(parent["props"])
                managed.update(parent["managed"])
                managed_scopes.update(parent["managed_scopes"])
        gid, ver = text(root, "groupId") or pg, text(root, "version") or pv
        props.update({"project.version": ver, "project.groupId": gid, "pom.version": ver,
                      "project.parent.version": pv or "", "parent.version": pv or ""})
        pe = root.find(q("properties"))
        if pe is not None:
            for c in pe:
                props[c.tag.split("}")[-1]] = (c.text or "").strip()

        def sub(s):
            for _ in range(5):
                if s and "${" in s:
                    s = re.sub(r"\$\{([^}]+)\}", lambda m: props.get(m.group(1), m.group(0)), s)
            return s

        for d in root.findall(q("dependencyManagement/dependencies/dependency")):
            dg, da, dv = sub(text(d, "groupId")), sub(text(d, "artifactId")), sub(text(d, "version"))
            if text(d, "scope") == "import":
                bom = self._pom(dg, da, dv)
                for k, val in (bom or {}).get("managed", {}).items():
                    managed.setdefault(k, val)
            else:
                managed[(dg, da)] = dv
                if text(d, "scope"):
                    managed_scopes[(dg, da)] = sub(text(d, "scope"))
        deps = []
        for d in root.findall(q("dependencies/dependency")):
            dg, da = sub(text(d, "groupId")), sub(text(d, "artifactId"))
            # A dependency without a scope takes the one its (parent's) dependencyManagement gives, as in
            # Maven: Netty's parent manages mockito as test, which must not reach an app.
            scope = text(d, "scope") or managed_scopes.get((dg, da)) or "compile"
            if scope not in ("compile", "runtime") or text(d, "optional") == "true":
                continue
            dv = sub(text(d, "version")) or managed.get((dg, da))
            excludes = frozenset((sub(text(e, "groupId")), sub(text(e, "artifactId")))
                                 for e in d.findall(q("exclusions/exclusion")))
            deps.append((dg, da, concrete_version(dv), excludes))
        result = {"packaging": sub(text(root, "packaging")) or "jar", "props": props, "managed": managed,
                  "managed_scopes": managed_scopes, "deps": deps}
        self._poms[key] = result
        return result

    def node(self, g: str, a: str, v: str) -> Node:
        key = (g, a, v)
        if key in self._nodes:
            return self._nodes[key]
        node = Node()
        raw = self.repo.read(Repository.relative(g, a, v, f"{a}-{v}.module"))
        variant = self._variant(json.loads(raw)) if raw else None
        if variant is not None:
            if "available-at" in variant:
                at = variant["available-at"]
                node.redirect = (at["group"], at["module"], at["version"])
            else:
                base = Repository.relative(g, a, v, "")
                for f in variant.get("files", []):
                    node.files.append(_normalise(base + f["url"]))
                for d in variant.get("dependencies", []):
                    excludes = frozenset((e.get("group", "*"), e.get("module", "*")) for e in d.get("excludes", []))
                    node.deps.append((d["group"], d["module"], concrete_version(d.get("version", {})), excludes))
                for c in variant.get("dependencyConstraints", []):
                    cv = concrete_version(c.get("version", {}))
                    if cv:
                        node.constraints.append((c["group"], c["module"], cv))
        else:
            pom = self._pom(g, a, v)
            if pom is None:
                node.source = "missing"
            else:
                node.source = "pom"
                packaging = pom["packaging"]
                if packaging == "pom":  # a BOM: its managed versions act as constraints, as a Gradle platform
                    node.constraints = [(dg, da, concrete_version(dv)) for (dg, da), dv in pom["managed"].items() if dv]
                else:
                    ext = "aar" if packaging == "aar" else "jar"
                    node.files.append(Repository.relative(g, a, v, f"{a}-{v}.{ext}"))
                node.deps = pom["deps"]
        self._nodes[key] = node
        return node

    def _prefetch(self, queue, requested, constraints, previous_constraints, forced, seen) -> None:
        """Reads the metadata of every queued module in parallel: resolution is bound by round trips."""
        wanted = set()
        for ga, _ in queue:
            if ga in seen:
                continue
            versions = requested[ga] | previous_constraints.get(ga, set()) | constraints.get(ga, set())
            if versions:
                key = (ga[0], ga[1], forced.get(ga) or highest(versions))
                if key not in self._nodes:
                    wanted.add(key)
        if len(wanted) > 1:
            with ThreadPoolExecutor(max_workers=8) as pool:
                list(pool.map(lambda k: self.node(*k), wanted))

    # -- resolution -------------------------------------------------------------------------------
    def resolve(self, roots: list[tuple]) -> list[Artifact]:
        """Runtime classpath of `roots` (versionless roots take their version from platforms among them).

        A root is (group, name, version) or (group, name, version, excludes): Gradle's exclude rules on a
        declared dependency, (group, module or "*") pairs left out of that dependency's graph."""
        root_excludes = {(r[0], r[1]): (r[3] if len(r) > 3 else frozenset()) for r in roots}
        roots = [r[:3] for r in roots]
        forced: dict[tuple, str] = {}
        previous_constraints: dict[tuple, set] = {}
        for _ in range(50):
            requested, constraints = defaultdict(set), defaultdict(set)
            for g, a, v in roots:
                if v:
                    requested[(g, a)].add(v)
            seen, selected = set(), {}
            queue = [((g, a), root_excludes[(g, a)]) for g, a, _ in roots]
            while queue:
                self._prefetch(queue, requested, constraints, previous_constraints, forced, seen)
                ga, _excl = queue.pop()
                if ga in seen:
                    continue
                versions = requested[ga] | previous_constraints.get(ga, set()) | constraints.get(ga, set())
                if not versions:
                    continue  # versionless: a platform constraint supplies it in the next round
                seen.add(ga)
                v = forced.get(ga) or highest(versions)
                n = self.node(ga[0], ga[1], v)
                selected[ga] = v
                if n.redirect:
                    rg, ra, rv = n.redirect
                    requested[(rg, ra)].add(rv)
                    queue.append(((rg, ra), frozenset()))
                for dg, da, dv, excl in n.deps:
                    if (dg, da) in _excl or (dg, "*") in _excl or ("*", "*") in _excl:
                        continue
                    if dv:
                        requested[(dg, da)].add(dv)
                    queue.append(((dg, da), excl | _excl))
                for cg, ca, cv in n.constraints:
                    constraints[(cg, ca)].add(cv)
            new = {ga: highest(requested[ga] | constraints.get(ga, set())) for ga in seen}
            if new == forced and set(constraints) == set(previous_constraints):
                missing = [f"{g}:{a}:{new[(g, a)]}" for (g, a) in sorted(seen)
                           if self.node(g, a, new[(g, a)]).source == "missing"]
                if missing:
                    raise BuildError("not on Maven Central: " + ", ".join(missing))
                unresolved = [f"{g}:{a}" for g, a, v in roots if (g, a) not in seen]
                if unresolved:
                    raise BuildError("no version for " + ", ".join(unresolved) + " (declare one or add its platform/BOM)")
                out = []
                for g, a in sorted(seen):
                    n = self.node(g, a, new[(g, a)])
                    out.append(Artifact(g, a, new[(g, a)], list(n.files)))
                return out
            forced = new
            previous_constraints = {k: set(v) for k, v in constraints.items()}
        raise BuildError("dependency resolution did not converge")


def _normalise(rel: str) -> str:
    parts = []
    for p in rel.split("/"):
        if p == "..":
            parts.pop()
        elif p and p != ".":
            parts.append(p)
    return "/".join(parts)
