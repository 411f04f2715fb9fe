"""Character counting (GRBL's interface documentation, "Streaming Protocol:
Character-Counting"): the host keeps the bytes of every line it sent and has not yet
seen answered, and sends a line only when the machine's receive buffer has room.

``CharCounter(capacity)``: ``fits(n)`` whether ``n`` more bytes fit now;
``sent(item, n)``; ``answered()`` pops and returns the oldest item (the one an ``ok``
or ``error:N`` answers; None if nothing was in flight); ``clear()`` after a reset
(GRBL empties its buffer). Each answer matches the oldest line: GRBL answers in order.
"""

from __future__ import annotations

from collections import deque

GRBL_RX_BUFFER = 128


class CharCounter:
    """Bytes in flight against a receive buffer of ``capacity`` bytes."""

    def __init__(self, capacity: int = GRBL_RX_BUFFER) -> None:
        self.capacity = capacity
        self.used = 0
        self._items: deque = deque()

    def fits(self, nbytes: int) -> bool:
        return self.used + nbytes <= self.capacity

    def sent(self, item, nbytes: int) -> None:
        self._items.append((item, nbytes))
        self.used += nbytes

    def answered(self):
        if not self._items:
            return None
        item, nbytes = self._items.popleft()
        self.used -= nbytes
        return item

    def oldest(self):
        return self._items[0][0] if self._items else None

    def items(self) -> list:
        return [item for item, _ in self._items]

    def __len__(self) -> int:
        return len(self._items)

    def clear(self) -> list:
        """Forget everything in flight (a reset); returns the items that were."""
        gone = self.items()
        self._items.clear()
        self.used = 0
        return gone
