"""The link to the machine: frame codec, session, transports; Qt only in worker.py."""
