"""Progress lines on stderr: one per stage, with its duration, so stdout stays clean for products. A long stage
also says every [HEARTBEAT_S] how long it has run and about how long is left, from the last run's duration on
this machine ([StageTimes]) or, before any, from a rate measured here."""
import json
import os
import sys
import threading
import time

QUIET = False
HEARTBEAT_S = 10.0


class Stage:
    def __init__(self, name: str, expected: float | None = None, times: "StageTimes | None" = None,
                 key: str | None = None):
        """`expected`: seconds this stage should take, for the heartbeat's estimate (none without it); `times`
        and `key`: where this run's duration is recorded for the next run's estimate."""
        self.name = name
        self.expected = expected
        self.times = times
        self.key = key or name
        self._stop = threading.Event()

    def __enter__(self):
        self.start = time.monotonic()
        if not QUIET:
            print(f"> {self.name}", file=sys.stderr, flush=True)
            if self.expected:
                threading.Thread(target=self._beat, daemon=True).start()
        return self

    def _beat(self):
        while not self._stop.wait(HEARTBEAT_S):
            print(f"  {self.name}: {progress(time.monotonic() - self.start, self.expected)}", file=sys.stderr,
                  flush=True)

    def __exit__(self, exc_type, exc, tb):
        self._stop.set()
        elapsed = time.monotonic() - self.start
        if exc_type is None:
            if not QUIET:
                print(f"  {self.name}: {elapsed:.1f} s", file=sys.stderr, flush=True)
            if self.times is not None:
                self.times.record(self.key, elapsed)
        return False


def progress(elapsed: float, expected: float) -> str:
    """`12 s, ~30 s left`, or once past the estimate `50 s, longer than the ~42 s expected`."""
    left = expected - elapsed
    return f"{elapsed:.0f} s, " + (f"~{left:.0f} s left" if left >= 1 else f"longer than the ~{expected:.0f} s expected")


class StageTimes:
    """Each long stage's last duration on this machine (`.build-cache/stage-times.json`), by key."""

    def __init__(self, path: str):
        self.path = path
        try:
            with open(path) as f:
                self.times = {k: float(v) for k, v in json.load(f).items()}
        except (OSError, ValueError, AttributeError):
            self.times = {}

    def expected(self, key: str, default: float) -> float:
        return self.times.get(key, default)

    def record(self, key: str, seconds: float) -> None:
        self.times[key] = round(seconds, 1)
        os.makedirs(os.path.dirname(self.path), exist_ok=True)
        with open(self.path + ".tmp", "w") as f:
            json.dump(self.times, f, indent=0, sort_keys=True)
        os.replace(self.path + ".tmp", self.path)


def info(message: str) -> None:
    if not QUIET:
        print(f"  {message}", file=sys.stderr, flush=True)
