"""Progress lines on stderr: one per stage, with its duration, so stdout stays clean for products."""
import sys
import time

QUIET = False


class Stage:
    def __init__(self, name: str):
        self.name = name

    def __enter__(self):
        self.start = time.monotonic()
        if not QUIET:
            print(f"> {self.name}", file=sys.stderr, flush=True)
        return self

    def __exit__(self, exc_type, exc, tb):
        if not QUIET and exc_type is None:
            print(f"  {self.name}: {time.monotonic() - self.start:.1f} s", file=sys.stderr, flush=True)
        return False


def info(message: str) -> None:
    if not QUIET:
        print(f"  {message}", file=sys.stderr, flush=True)
