"""Work around a refcount bug of shiboken6 6.12.0 on Python < 3.12.

In that combination Qt methods that return ``void`` (and some that return ``bool``)
hand Python ``None`` / ``True`` / ``False`` without counting the reference, so their
counts drop by one per call and the process aborts ("none_dealloc", "bool_dealloc")
after a few thousand calls. Python 3.12 made these objects immortal; here we make
them practically immortal by raising their counts once. Pinning
``PySide6-Essentials<6.12`` avoids the bug as well.
"""

import ctypes
import sys


def apply() -> bool:
    """Raise the reference counts of None, True, False if the buggy combination is present."""
    if sys.version_info >= (3, 12):
        return False
    import shiboken6

    if tuple(shiboken6.__version_info__[:2]) != (6, 12):
        return False
    for constant in (None, True, False):
        count = ctypes.c_ssize_t.from_address(id(constant))
        if count.value < 1 << 40:
            count.value += 1 << 50
    return True
