# Each target creates .venv with the machine's python3 if missing and installs the project.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
SAMPLE := resources/samples/README.md

# Translations (resources/i18n/): the window's Qt Linguist files, compiled to .qm (English
# is the source language: its file holds only the plural forms), and the core's gettext
# catalogue, compiled to .mo. `make i18n` collects new strings into them (then translate
# the new entries); `run` and `test` recompile what changed.
I18N := resources/i18n
TS := $(I18N)/cnc_vi.ts $(I18N)/cnc_en.ts
QM := $(TS:.ts=.qm)
POT := $(I18N)/cnc.pot
PO := $(I18N)/vi/LC_MESSAGES/cnc.po
MO := $(PO:.po=.mo)
UI_SOURCES = $(shell find app/ui -name '*.py' | sort)
CORE_SOURCES = app/i18n.py app/atomic.py app/profile.py app/ui/settings/store.py app/ui/settings/prefs.py app/ui/settings/commands.py app/gcode app/comm

.PHONY: run test bench lint clean i18n translations bytecode

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)

$(STAMP): $(BIN)/python pyproject.toml
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

%.qm: %.ts | $(STAMP)
	$(BIN)/pyside6-lrelease -silent $< -qm $@

%.mo: %.po | $(STAMP)
	$(BIN)/pybabel -q compile --use-fuzzy -D cnc -i $< -o $@

translations: $(QM) $(MO)

i18n: $(STAMP)
	$(BIN)/pyside6-lupdate -silent -no-obsolete -locations none $(UI_SOURCES) -ts $(I18N)/cnc_vi.ts
	$(BIN)/pyside6-lupdate -silent -no-obsolete -locations none -pluralonly $(UI_SOURCES) -ts $(I18N)/cnc_en.ts
	$(BIN)/pybabel -q extract --no-location --omit-header -k msg -k N_ -o $(POT) $(CORE_SOURCES)
	$(BIN)/pybabel -q update --ignore-obsolete --ignore-pot-creation-date --no-fuzzy-matching -D cnc -i $(POT) -d $(I18N)
	$(MAKE) translations

# The project is installed editable, so pip compiles none of its modules: compile them
# (as an installed package is) so that a start reads bytecode even where the environment
# writes none (PYTHONDONTWRITEBYTECODE); only what changed is compiled again.
bytecode: $(STAMP)
	$(BIN)/python -m compileall -q app backend_sim

run: $(STAMP) translations bytecode
	$(BIN)/python -m app.run

# One test process per core (pytest-xdist), idle ones taking tests from busy ones: the
# suite's wall-clock checks are written to hold on a machine that is busy.
test: $(STAMP) translations bytecode
	QT_QPA_PLATFORM=offscreen $(BIN)/python -m pytest -q -n auto --dist worksteal

bench: $(STAMP) bytecode
	QT_QPA_PLATFORM=offscreen $(BIN)/python -m bench

lint: $(STAMP)
	$(BIN)/ruff check app backend_sim tests bench

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache bench/data
