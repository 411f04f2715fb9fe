"""The main MCU's ``SD`` commands, the ``SD PUT`` stream and the glue of ``SD RUN``.

Contract (docs/protocol.md): ``SD LIST`` -> ``I <id> <name> <bytes> <lines>`` rows then
``O <id> SD LIST <count>``; ``SD DEL <name>`` -> ``O``; ``SD PUT <name> <lines>
<crc32hex>`` -> ``E`` at once (BAD_NAME, SD_FULL, BUSY, BAD_ARGS; BUSY also for the file an ``SD RUN``
is running) or, after the stream of ``D`` frames (acked ``A`` by the main MCU itself),
one ``O <id> SD PUT <name>`` or ``E <id> CRC_MISMATCH``; a card that cannot take a line
ends the upload at that line with ``E <id> SD_FULL`` (or ``SD_ERROR``), no file left;
``SD RUN <name>`` -> ``O <id> SD RUN <name>`` when the CNC MCU
has opened the job (status flag ``S`` while it runs). Functions take the ``MainMcu``.
"""

from __future__ import annotations

from app.comm.frame import Ack, Alarm, Command, Data, Error, Finished, Frame, Info, Log, Nak, Ok
from backend_sim.job_stream import Verdict
from backend_sim.outgoing import encode_fit
from backend_sim.sd_card import UPLOAD_FREE_SLOTS, SdError, write_error
from backend_sim.sd_job import SdJob, SdJobState


def command(mcu, cmd: Command) -> None:
    sub = cmd.args[0] if cmd.args else ""
    handler = _SUB.get(sub)
    try:
        if handler is None:
            raise SdError("UNKNOWN_VERB", f"SD {sub}: LIST, PUT, DEL or RUN")
        handler(mcu, cmd)
    except SdError as exc:
        mcu.answer(Error(cmd.id, exc.code, exc.text))
    except OSError as exc:  # the card failed under a LIST, DEL or RUN: said, never fatal
        error = write_error(" ".join(cmd.args[1:2]) or "card", exc)
        mcu.answer(Error(cmd.id, error.code, error.text))


def _arg(cmd: Command, count: int) -> tuple[str, ...]:
    if len(cmd.args) != count + 1:
        raise SdError("BAD_ARGS", f"SD {cmd.args[0]} takes {count} argument(s)")
    return cmd.args[1:]


def _list(mcu, cmd: Command) -> None:
    _arg(cmd, 0)
    rows = mcu.sd.list()
    for name, size, lines in rows:
        mcu.answer(Info(cmd.id, f"{name} {size} {lines}"))
    mcu.answer(Ok(cmd.id, "SD", f"LIST {len(rows)}"))


def _delete(mcu, cmd: Command) -> None:
    (name,) = _arg(cmd, 1)
    if mcu.sd_job is not None and mcu.sd_job.name == name:
        raise SdError("BUSY", f"{name} is running")
    mcu.sd.delete(name)
    mcu.answer(Ok(cmd.id, "SD", f"DEL {name}"))


def _put(mcu, cmd: Command) -> None:
    name, lines, crc = _arg(cmd, 3)
    if mcu.upload is not None:
        raise SdError("BUSY", "an upload is in progress")
    if not lines.isdigit():
        raise SdError("BAD_ARGS", f"line count {lines!r}")
    if mcu.sd_job is not None and mcu.sd_job.name == name:
        raise SdError("BUSY", f"{name} is running")
    mcu.upload = mcu.sd.begin_put(name, int(lines), crc)
    mcu.upload_id = cmd.id


def _run(mcu, cmd: Command) -> None:
    (name,) = _arg(cmd, 1)
    start_job(mcu, name, lambda frame: _run_answer(mcu, cmd.id, frame))


def _run_answer(mcu, cid: int, frame: Frame) -> None:
    answer = Ok(cid, "SD", f"RUN {mcu.sd_job.name}") if isinstance(frame, Ok) else frame
    if isinstance(answer, Error):
        answer = Error(cid, answer.code, answer.text)
    if cid == mcu.last_id:
        mcu.answer(answer)
    else:
        mcu.to_host(answer)


_SUB = {"LIST": _list, "DEL": _delete, "PUT": _put, "RUN": _run}


# ---------------------------------------------------------------------- SD PUT stream


def upload_data(mcu, frame: Data) -> None:
    up = mcu.upload
    verdict = up.stream.offer(frame.seq)
    if verdict is Verdict.REACK:
        mcu.answer(Ack(up.stream.expected - 1, UPLOAD_FREE_SLOTS))
    elif verdict in (Verdict.NAK, Verdict.QUIET):
        up.stream.keep(frame.seq, frame.line, UPLOAD_FREE_SLOTS)  # selective repeat
        if verdict is Verdict.NAK:
            mcu.answer(Nak(up.stream.expected))
    elif verdict is Verdict.QUEUE:
        _store(mcu, up, frame.seq, frame.line)
        kept = up.stream.take()
        while kept is not None and mcu.upload is up:
            _store(mcu, up, *kept)
            kept = up.stream.take()
        if mcu.upload is up and up.stream.gap_remains():
            mcu.answer(Nak(up.stream.expected))


def _store(mcu, up, seq: int, line: str) -> None:
    try:
        up.write(seq, line)
    except SdError as exc:  # the card is full: the upload is over, its file removed
        mcu.upload = None
        mcu.notice = f"SD PUT {up.name}: {exc.code}"
        _upload_answer(mcu, mcu.upload_id, Error(mcu.upload_id, exc.code, exc.text))
        return
    mcu.host_tx.write(Ack(seq, UPLOAD_FREE_SLOTS).encode(), mcu.clock.now)
    if up.complete:
        _finish_upload(mcu)


def abandon_upload(mcu, reason: str) -> None:
    """End an unfinished ``SD PUT`` (host lost, STOP, reset): its partial file is
    removed, the card's files stay as they were, ``L`` says so when the host listens."""
    up, mcu.upload = mcu.upload, None
    if up is None:
        return
    up.abort()
    mcu.notice = f"SD PUT {up.name} abandoned"
    mcu.to_host(Log(f"SD PUT {up.name} abandoned: {reason}"))


def upload_bad_frame(mcu) -> None:
    if mcu.upload.stream.bad_frame() is Verdict.NAK:
        mcu.to_host(Nak(mcu.upload.stream.expected))


def _finish_upload(mcu) -> None:
    up, cid = mcu.upload, mcu.upload_id
    mcu.upload = None
    try:
        up.finish()
    except SdError as exc:
        _upload_answer(mcu, cid, Error(cid, exc.code, exc.text))
    else:
        _upload_answer(mcu, cid, Ok(cid, "SD", f"PUT {up.name}"))


def _upload_answer(mcu, cid: int, frame: Frame) -> None:
    if cid == mcu.last_id:
        mcu.answer(frame)
    else:
        mcu.host_tx.write(encode_fit(frame), mcu.clock.now)


# ---------------------------------------------------------------------- SD RUN


def start_job(mcu, name: str, on_open=None) -> None:
    """Start streaming ``name`` to the CNC MCU; ``on_open(frame)`` gets the JOB's O or E."""
    if mcu.sd_job is not None or mcu.upload is not None:
        raise SdError("BUSY", "an SD job or upload is in progress")
    lines = mcu.sd.read_lines(name)
    if not lines:
        raise SdError("NO_FILE", f"{name} is empty")
    cid = mcu.own_id + 1
    mcu.own_pending[cid] = lambda frame: _job_opened(mcu, frame, on_open)
    mcu.own_id = cid
    mcu.sd_job = SdJob(name, lines, cid, mcu.to_cnc, mcu.clock.now)
    mcu.notice = f"SD {name}"


def _job_opened(mcu, frame: Frame, on_open) -> None:
    job = mcu.sd_job
    if job is None:
        return
    if isinstance(frame, Ok):
        job.opened(mcu.clock.now)
    else:
        job.fail(f"{frame.code} {frame.text}")
        mcu.sd_job = None
        mcu.notice = f"SD: {frame.code}"
    if on_open is not None:
        on_open(frame)


def job_frame(mcu, frame: Frame) -> bool:
    """Take the SD job's A/N/F (and a refused line); True when the frame was consumed."""
    job, now = mcu.sd_job, mcu.clock.now
    if isinstance(frame, Ack):
        job.on_ack(frame.seq, frame.free, now)
    elif isinstance(frame, Nak):
        job.on_nak(frame.seq, now)
    elif isinstance(frame, Finished):
        job.on_finished(frame.seq, now)
    elif isinstance(frame, Error) and frame.id is None or isinstance(frame, Alarm):
        job.fail(f"{frame.code} {frame.text}")
        return False
    else:
        return False
    return True


def check_job(mcu) -> None:
    job = mcu.sd_job
    if job is None or job.active:
        return
    mcu.sd_job = None
    text = f"SD {job.name} done" if job.state is SdJobState.DONE else f"SD {job.name}: {job.error}"
    mcu.notice = text
    mcu.to_host(Log(text))


def stop_job(mcu, text: str) -> None:
    if mcu.sd_job is not None:
        mcu.sd_job.fail(text)
        check_job(mcu)
