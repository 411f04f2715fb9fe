"""A disk that fills up: the OSError(ENOSPC) a real full disk raises, at any byte.

``FullDisk(budget)`` lets ``budget`` bytes through in all, then every write fails.
``open(path, mode)`` gives a file over a real one: a buffered-style file (``raw=False``)
writes what fits and raises, as ``BufferedWriter`` does when its flush hits ENOSPC; a
raw one (``raw=True``) returns a short count first and raises on the next write, as
``os.write`` does.
"""

from __future__ import annotations

import errno


class FullDisk:
    def __init__(self, budget: int, raw: bool = False) -> None:
        self.left, self.raw = budget, raw
        self.failures = 0

    def open(self, path, mode: str = "wb"):
        return _FullFile(open(path, mode, buffering=0), self)  # noqa: SIM115


class _FullFile:
    def __init__(self, file, disk: FullDisk) -> None:
        self.file, self.disk = file, disk

    def write(self, data) -> int:
        data = bytes(data)
        disk = self.disk
        if disk.left <= 0:
            disk.failures += 1
            raise OSError(errno.ENOSPC, "No space left on device")
        fits = min(len(data), disk.left)
        self.file.write(data[:fits])
        disk.left -= fits
        if fits < len(data) and not disk.raw:
            disk.failures += 1
            raise OSError(errno.ENOSPC, "No space left on device")
        return fits

    def __getattr__(self, name):
        return getattr(self.file, name)

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.file.close()
