"""Maven Central access with a local cache in the standard Maven repository layout.

Files are verified against the SHA-1 that Central publishes beside them. A 404 is remembered with
a `.404` marker so repeated resolutions stay offline.
"""
from __future__ import annotations

import hashlib
import os
import threading
import time
import urllib.error
import urllib.request
from concurrent.futures import ThreadPoolExecutor

from .errors import BuildError

CENTRAL = os.environ.get("HAPTICON_MAVEN_URL", "https://repo.maven.apache.org/maven2")


def default_repository() -> str:
    return os.environ.get("HAPTICON_M2") or os.path.join(os.path.expanduser("~"), ".m2", "repository")


class Repository:
    def __init__(self, local: str | None = None, offline: bool = False):
        self.local = local or default_repository()
        self.offline = offline or os.environ.get("HAPTICON_OFFLINE") == "1"
        self._lock = threading.Lock()
        self.downloaded_bytes = 0
        self.downloaded_files = 0

    @staticmethod
    def relative(group: str, artifact: str, version: str, filename: str) -> str:
        return f"{group.replace('.', '/')}/{artifact}/{version}/{filename}"

    def path(self, rel: str) -> str:
        return os.path.join(self.local, rel)

    def fetch(self, rel: str, verify: bool = False) -> str | None:
        """Local path of `rel`, downloading it if needed; None when Central has no such file."""
        local = self.path(rel)
        if os.path.exists(local):
            return local
        if os.path.exists(local + ".404"):
            return None
        if self.offline:
            raise BuildError(f"{rel} is not in {self.local} and HAPTICON_OFFLINE=1")
        data = self._download(rel)
        if data is None:
            os.makedirs(os.path.dirname(local), exist_ok=True)
            open(local + ".404", "w").close()
            return None
        if verify:
            self._verify(rel, data)
        os.makedirs(os.path.dirname(local), exist_ok=True)
        tmp = f"{local}.part{threading.get_ident()}"
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, local)
        with self._lock:
            self.downloaded_bytes += len(data)
            self.downloaded_files += 1
        return local

    def read(self, rel: str) -> bytes | None:
        p = self.fetch(rel)
        if p is None:
            return None
        with open(p, "rb") as f:
            return f.read()

    def _download(self, rel: str) -> bytes | None:
        url = f"{CENTRAL}/{rel}"
        for attempt in range(4):
            try:
                with urllib.request.urlopen(url, timeout=120) as r:
                    return r.read()
            except urllib.error.HTTPError as e:
                if e.code == 404:
                    return None
                error = e
            except (urllib.error.URLError, TimeoutError, ConnectionError) as e:
                error = e
            time.sleep(1.5 * (attempt + 1))
        raise BuildError(f"cannot download {url}: {error}")

    def _verify(self, rel: str, data: bytes) -> None:
        expected = self._download(rel + ".sha1")
        if expected is None:
            return  # Central has a few old artifacts without checksums
        want = expected.decode("ascii", "replace").strip().split()[0].lower()
        got = hashlib.sha1(data).hexdigest()
        if want != got:
            raise BuildError(f"checksum mismatch for {rel}: expected {want}, got {got}")

    def fetch_all(self, rels: list[str], workers: int = 8) -> list[str]:
        """Download many artifact files in parallel (verified); returns their local paths in order."""
        def one(rel: str) -> str:
            p = self.fetch(rel, verify=True)
            if p is None:
                raise BuildError(f"Maven Central has no {rel}")
            return p
        with ThreadPoolExecutor(max_workers=workers) as pool:
            return list(pool.map(one, rels))
