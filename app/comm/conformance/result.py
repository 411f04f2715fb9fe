"""What the kit found: one ``Result`` per check, and the table a firmware author reads.

A result names the rule (``rule``: what docs/protocol.md says, ``section``: where),
what the kit sent, what came back, and the outcome: ``pass``, ``fail`` or ``skip``
(a rule the wire cannot show, with the reason). ``render_text`` prints the table,
``render_markdown`` and ``render_json`` write ``--report FILE``.
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass

PASS, FAIL, SKIP = "pass", "fail", "skip"
CELL = 70


@dataclass
class Result:
    id: str
    section: str
    rule: str
    outcome: str
    sent: str = ""
    got: str = ""
    note: str = ""


def failed(results: list[Result]) -> list[Result]:
    return [r for r in results if r.outcome == FAIL]


def _cut(text: str, width: int = CELL) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= width else text[: width - 3] + "..."


def summary(results: list[Result]) -> str:
    counts = {k: sum(r.outcome == k for r in results) for k in (PASS, FAIL, SKIP)}
    return f"{counts[PASS]} passed, {counts[FAIL]} failed, {counts[SKIP]} not checked from the wire"


def render_text(results: list[Result]) -> str:
    """The table for the terminal: one block per check, failures in full."""
    lines = []
    for r in results:
        lines.append(f"{r.outcome.upper():4}  {r.id:34} [{r.section}]")
        if r.outcome != PASS:
            lines.append(f"      doc says: {r.rule}")
            if r.sent:
                lines.append(f"      sent:     {_cut(r.sent, 200)}")
            if r.got:
                lines.append(f"      got:      {_cut(r.got, 200)}")
            if r.note:
                lines.append(f"      note:     {r.note}")
    lines.append(summary(results))
    return "\n".join(lines)


def _md(text: str) -> str:
    return _cut(text, 160).replace("|", "\\|") or " "


def render_markdown(results: list[Result], title: str) -> str:
    rows = [
        f"# Conformance of {title} to docs/protocol.md",
        "",
        summary(results),
        "",
        "| outcome | check | section | doc says | sent | got | note |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in results:
        rows.append(
            f"| {r.outcome} | `{r.id}` | {_md(r.section)} | {_md(r.rule)} | {_md(r.sent)} | "
            f"{_md(r.got)} | {_md(r.note)} |"
        )
    return "\n".join(rows) + "\n"


def render_json(results: list[Result], title: str) -> str:
    return (
        json.dumps(
            {"port": title, "summary": summary(results), "results": [asdict(r) for r in results]}, indent=2
        )
        + "\n"
    )
