"""Finding what a call names: LinuxCNC subroutines and Fanuc subprograms.

A LinuxCNC ``o<name> call`` (or ``o100 call``) runs the ``sub`` of that name in the
calling file, else in the main file, else in ``name.ngc`` in the program's folder or
its ``subs`` folder (a name with a path is refused). A Fanuc ``M98 Pn`` / ``G65 Pn``
runs program ``On`` of the calling file, else of the main file, else the file
``Onnnn.nc``, ``onnnn.nc`` or ``nnnn.nc`` (four digits, or the number as written) in
the same folders. Every file read passes the main file's checks (``reading.py``).
``Library`` compiles each file once.
"""

from __future__ import annotations

import os
from pathlib import Path

from app.gcode.reading import SourceError, clean_bytes, read_source, text_problem
from app.i18n import msg

from . import structure
from .errors import MacroError
from .structure import Unit

SUBS = "subs"  # the folder beside the program where subprogram files are looked for too

# Fanuc argument specification I: address -> local number
FANUC_ARGUMENTS = {"A": 1, "B": 2, "C": 3, "I": 4, "J": 5, "K": 6, "D": 7, "E": 8, "F": 9, "H": 11,
                   "M": 13, "Q": 17, "R": 18, "S": 19, "T": 20, "U": 21, "V": 22, "W": 23,
                   "X": 24, "Y": 25, "Z": 26}
IJK_SETS = 10  # specification II: up to ten sets of I J K, into #4-#33


def fanuc_arguments(pairs) -> dict[int, float]:
    """The locals a ``G65`` line's argument words (letter, value), in line order, set.

    Specification I maps each letter to its number (``FANUC_ARGUMENTS``); I, J and K
    may also come as up to ten sets (specification II): a letter that does not follow
    the one before in the order I J K starts the next set, whose I J K are #4+3k,
    #5+3k, #6+3k. Where both give a number, the later word wins (as the control)."""
    found: dict[int, float] = {}
    group, last = 0, -1
    for letter, value in pairs:
        if letter in "IJK":
            index = "IJK".index(letter)
            if index <= last:
                group += 1
            last = index
            if group >= IJK_SETS:
                raise MacroError(msg("G65 takes at most {sets} sets of I J K (argument specification II)",
                                     sets=IJK_SETS))
            found[4 + 3 * group + index] = value
        elif letter in FANUC_ARGUMENTS:
            found[FANUC_ARGUMENTS[letter]] = value
    return found


def read_lines(path: Path) -> list[str]:
    """The lines of a subprogram file, or a ``MacroError`` saying why not: the main file's
    checks (``reading.py``: a regular file, the size limit, UTF-8 text without NUL bytes)."""
    try:
        raw = clean_bytes(read_source(path))
    except SourceError as exc:
        raise MacroError(exc.args[0]) from None
    problem = text_problem(raw)
    if problem:
        raise MacroError(msg("{path}: {problem}", path=str(path), problem=problem))
    text = raw.decode("utf-8")
    return [line[:-1] if line.endswith("\r") else line for line in text.split("\n")]


MAX_NAME = 128  # characters of a subprogram's name (its file name must fit the system's limit)


def check_name(name: str, what: str) -> None:
    """Refuse a name that is not a plain file name: a path (``../x``, ``/abs``) would read
    files outside the program's folders."""
    if "/" in name or "\\" in name or name in (".", "..") or "\x00" in name:
        raise MacroError(msg("{what}: a subprogram's name cannot hold a path (its file is looked for "
                             "only beside the program and in its subs folder)", what=what))
    if len(name) > MAX_NAME:
        raise MacroError(msg("{what}: the name is longer than {limit} characters", what=what[:40] + "...",
                             limit=MAX_NAME))


class Library:
    """The compiled files of one expansion: file id -> ``Unit`` (0 is the main file)."""

    def __init__(self, main: Unit, folder: Path | None):
        self.units: list[Unit] = [main]
        self.folder = folder
        self._by_path: dict[Path, int] = {}

    def _load(self, path: Path) -> int:
        file_id = self._by_path.get(path)
        if file_id is None:
            main = self.units[0]
            lines = read_lines(path)
            left = structure.MAX_LINES - sum(u.compiled for u in self.units)
            if left <= 0:
                raise structure.too_many_lines()
            unit = Unit(str(path), lines, main.fanuc, main.block_delete, left)
            if unit.errors:
                raise unit.errors[0]
            file_id = len(self.units)
            self.units.append(unit)
            self._by_path[path] = file_id
        return file_id

    def _find_file(self, names: list[str], what: str) -> int:
        if self.folder is None:
            raise MacroError(msg("{what} is not defined (a program without a folder cannot use other files)",
                                 what=what))
        folders = (self.folder, self.folder / SUBS)
        for folder in folders:
            for name in names:
                if (folder / name).exists():
                    return self._load(folder / name)
        raise MacroError(msg("{what} is not defined in this file, nor as {file} in {folder} or {subs}",
                             what=what, file=names[0], folder=os.path.abspath(folders[0]),
                             subs=os.path.abspath(folders[1])))

    def subroutine(self, name: str, caller: int) -> tuple[int, int]:
        """(file id, index of the ``sub`` block) of the LinuxCNC subroutine ``name``."""
        for file_id in (caller, 0):
            if name in self.units[file_id].subs:
                return file_id, self.units[file_id].subs[name]
        what = msg("subroutine o<{name}>", name=name)
        check_name(name, what)
        file_id = self._find_file([f"{name}.ngc"], what)
        if name not in self.units[file_id].subs:
            raise MacroError(msg("{file} does not define o<{name}> sub", file=self.units[file_id].name,
                                 name=name))
        return file_id, self.units[file_id].subs[name]

    def program(self, number: int, caller: int) -> tuple[int, int]:
        """(file id, first block) of the Fanuc program ``O<number>``."""
        for file_id in (caller, 0):
            if number in self.units[file_id].programs:
                return file_id, self.units[file_id].programs[number]
        names = [f"O{number:04d}.nc", f"o{number:04d}.nc", f"{number:04d}.nc",
                 f"O{number}.nc", f"o{number}.nc", f"{number}.nc"]
        file_id = self._find_file(list(dict.fromkeys(names)), msg("subprogram O{number:04d}", number=number))

        return file_id, self.units[file_id].programs.get(number, 0)
