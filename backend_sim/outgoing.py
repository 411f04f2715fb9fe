"""Encoding of the frames the MCUs send: never over 96 bytes.

``encode_fit(frame)`` is ``frame.encode()``, except that a body too long for one frame
(a long error text, a log line) is cut to fit, as firmware with a fixed TX buffer would.
"""

from __future__ import annotations

from app.comm.frame import MAX_BODY, Frame, FrameError, seal


def encode_fit(frame: Frame) -> bytes:
    try:
        return frame.encode()
    except FrameError:
        body = frame.body().encode("ascii", "replace").decode("ascii")
        printable = "".join(ch if " " <= ch <= "~" else "?" for ch in body)
        return seal(printable[:MAX_BODY].rstrip())
