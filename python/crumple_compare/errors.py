"""The one error type of the compare tool: a message that names the file and, where known, the
line (`path:line: message`), as Crumple's deck errors do (ARCHITECTURE.md, Errors)."""


class CompareError(Exception):
    """Bad input or an impossible request; the command prints it and exits with status 1."""

    def __init__(self, message, path=None, line=None):
        where = ""
        if path is not None:
            where = f"{path}:{line}: " if line is not None else f"{path}: "
        super().__init__(where + message)
