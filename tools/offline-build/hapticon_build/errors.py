class BuildError(Exception):
    """A problem the user can fix: printed as one clear line, never as a traceback."""
