"""Tool words of a line, as rs274ngc reads them: ``T`` (select), ``M6`` (change),
``M61 Q`` (set the tool in the spindle), ``G43 H``/``G43.1``/``G49`` (tool length
offset) and ``G10 L1/L10/L11`` (write a tool table entry for the rest of the program).

The table is ``State.tools`` (``dict[int, tools.Tool]``, millimetres), replaced and
never changed in place, so a refused line leaves it as it was. A tool that is not
in the table is refused as rs274 refuses it ("Requested tool N not found").
"""

from __future__ import annotations

from app.i18n import msg

from . import offsets
from .errors import LineError
from .tools import Tool, ToolError


def _number(word, what: str) -> int:
    value = word.value
    if value != int(value) or value < 0:
        raise LineError(word.column, msg("{word} {value} is not a tool number (a whole number >= 0)",
                                         word=what, value=f"{value:g}"))
    return int(value)


def find(state, number: int, column: int) -> Tool:
    """The table entry of tool ``number`` (0: no tool, all zero)."""
    if number == 0:
        return _NO_TOOL
    tool = state.tools.get(number)
    if tool is None:
        raise LineError(column, msg("Requested tool {number} not found in the tool table", number=number))
    return tool


class _NoTool:
    number, diameter, length, comment, radius = 0, 0.0, 0.0, "", 0.0


_NO_TOOL = _NoTool()


def select(state, params) -> bool:
    """A T word: the tool the next M6 puts in the spindle. False when the tool is not
    in the table (rs274 refuses it; a one-tool machine runs it with the warning the
    caller gives: its length and diameter read 0)."""
    if "T" not in params:
        return True
    number = _number(params["T"], "T")
    state.selected = number
    return number == 0 or number in state.tools


def change(state, kind: str, params, column: int) -> None:
    """M6 (the selected tool goes in) or M61 Q (the spindle holds tool Q, no pause)."""
    if kind == "set":
        if "Q" not in params:
            raise LineError(column, msg("M61 needs a Q word (the tool number)"))
        number = _number(params["Q"], "Q")
        find(state, number, params["Q"].column)
    else:
        number = state.selected
    state.tool = number


def length_offset(state, code: float, params, column: int) -> None:
    """G43 [H] (the table length of tool H, default the tool in the spindle),
    G43.1 [X] [Z] (given values) or G49 (none)."""
    if code == 43:
        number = _number(params["H"], "H") if "H" in params else state.tool
        tool = find(state, number, params["H"].column if "H" in params else column)
        offsets.set_tool_offset(state, [0.0, 0.0, tool.length])
    elif code == 43.1:
        if "Y" in params:
            raise LineError(params["Y"].column, msg("G43.1: Y tool offset not allowed (X and Z only)"))
        values = [params[c].value * state.scale if c in params else 0.0 for c in "XYZ"]
        offsets.set_tool_offset(state, values)
    else:
        offsets.set_tool_offset(state, [0.0, 0.0, 0.0])


def _fanuc(level: int, params) -> bool:
    """Fanuc's G10 L10-L13 (P tool, R value, no Z): L10 length, L12 radius geometry;
    L11/L13 are wear, which this table does not keep."""
    return level in (12, 13) or level in (10, 11) and "R" in params and "Z" not in params


def _fanuc_entry(state, level: int, params, column: int, old) -> tuple[float, float]:
    if level in (11, 13):
        raise LineError(column, msg("{code} (Fanuc wear offset) is not supported: the tool table keeps "
                                    "no wear; set the worn value with L10 (length) or L12 (radius)",
                                    code=f"G10 L{level}"))
    if "R" not in params:
        raise LineError(column, msg("{code} needs an R word (the value)", code=f"G10 L{level}"))
    value = params["R"].value * state.scale
    return (old.diameter, value) if level == 10 else (2 * value, old.length)


def set_entry(state, level: int, params, column: int) -> None:
    """G10 L1 P R Z (given), L10 (length so the current point reads Z with G43),
    L11 (the same in G59.3 without G92): the program's copy of the table changes.
    Fanuc's forms (R and no Z; L12, L13) are read as Fanuc means them (``_fanuc``)."""
    if "P" not in params:
        raise LineError(column, msg("{code} needs a P word (the tool number)", code=f"G10 L{level}"))
    number = _number(params["P"], "P")
    if state.fanuc and _fanuc(level, params) and number not in state.tools and number > 0:
        old = Tool(number, 0.0, 0.0, "")  # a Fanuc offset register: it exists whatever tools do
    else:
        old = find(state, number, params["P"].column)
    if number == 0:
        raise LineError(params["P"].column, msg("{code}: P0 is no tool", code=f"G10 L{level}"))
    diameter, length = old.diameter, old.length
    if _fanuc(level, params):
        diameter, length = _fanuc_entry(state, level, params, column, old)
    elif "R" in params:
        diameter = 2 * params["R"].value * state.scale
    if "Z" in params and not _fanuc(level, params):
        z = params["Z"].value * state.scale
        if level == 1:
            length = z
        elif level == 10:
            off = state.offsets
            length = state.pos[2] - off.g5x[2] - off.g92[2] - z
        else:
            length = state.pos[2] - state.param(offsets.system_param(9, 2)) - z
    try:
        new = Tool(number, diameter, length, old.comment)
    except ToolError as exc:
        raise LineError(column, exc.args[0]) from None
    state.tools = {**state.tools, number: new}


TOOL_NUMBER, TOOL_OFFSETS, TOOL_DIAMETER, POSITION = 5400, 5401, 5410, 5420


def publish(state) -> None:
    """Write the parameters derived from ``state`` into ``state.params``, as LinuxCNC keeps
    them: #5400 the tool in the spindle, #5401-#5409 its length offsets (X Y Z A B C U V
    W), #5410 its diameter, #5420-#5428 the current point in program coordinates and
    units. The expander calls this before a macro reads #5000 and up."""
    params, scale = state.params, state.scale
    entry = state.tools.get(state.tool)
    params.set(TOOL_NUMBER, state.tool)
    for i in range(9):
        value = state.offsets.tool[i] / scale if i < 3 else 0.0
        params.set(TOOL_OFFSETS + i, value)
    params.set(TOOL_DIAMETER, (entry.diameter if entry is not None else 0.0) / scale)
    point = state.program_pos()
    for i in range(9):
        params.set(POSITION + i, point[i] / scale if i < 3 else 0.0)
