"""A conformance kit for the machine's firmware: ``python -m app.comm.conformance PORT``.

An independent client written from docs/protocol.md alone (its own codec in
``wire``, its own streamer in ``stream``; nothing of the session or the simulator),
so a bug shared with the code under test cannot hide. ``runner.run(port)`` runs the
checks section by section (``checks_*``) and returns one ``Result`` per rule: what was
sent, what came back, what the document says and where.
"""
