"""The C heap of a process that loads one big program (glibc's malloc; elsewhere
nothing is changed)."""

from __future__ import annotations


def _glibc(name: str):
    """The C library's function ``name`` (glibc's malloc tuning), or None where there is none."""
    import ctypes

    try:
        return getattr(ctypes.CDLL(None), name)
    except (AttributeError, OSError):
        return None


def give_back_free_memory() -> None:
    """Return the heap's free pages to the system (glibc's ``malloc_trim``; elsewhere
    nothing): freed chunks in the middle of the heap otherwise stay resident, and the
    rest of a big load would add its peak on top of them."""
    trim = _glibc("malloc_trim")
    if trim is not None:
        trim(0)


M_TRIM_THRESHOLD, M_TOP_PAD, M_MMAP_THRESHOLD, M_ARENA_MAX = -1, -2, -3, -8  # glibc's mallopt parameters
ONE_SHOT_HEAP = ((M_ARENA_MAX, 1), (M_MMAP_THRESHOLD, 4 << 20), (M_TRIM_THRESHOLD, 256 << 20),
                 (M_TOP_PAD, 16 << 20))


def one_heap() -> None:
    """Set up the C heap (glibc's; elsewhere nothing) for a process that loads one program,
    before it starts a thread. Every thread allocates from the main heap (``M_ARENA_MAX``
    1: a thread's heap of its own kept freed temporaries resident, 25-30 MB more at the
    peak of a 1 M-line file). Blocks under 4 MB come from the heap and freed ones are kept
    there for the next (``M_TRIM_THRESHOLD`` 256 MB, the heap grown 16 MB at a time): a
    chunk's temporaries were handed back and touched anew, page by page, chunk after
    chunk; 4 MB and more (numpy asks the kernel for huge pages there) are mapped apart
    and unmapped when freed; the load gives the heap's free pages back itself after the
    scan (``give_back_free_memory``). arcs.ngc, 8 runs each: page faults 77,000 ->
    65,000, median wall 0.68 -> 0.64 s, the same peak (262 -> 264 MB)."""
    mallopt = _glibc("mallopt")
    if mallopt is not None:
        for parameter, value in ONE_SHOT_HEAP:
            mallopt(parameter, value)
