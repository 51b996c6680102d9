# Two commands do all the set-up on a fresh machine: `make run` and `make test`.
PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-$(shell cat pyproject.toml | sha1sum | cut -c1-12)
DEMO   ?= build a 3-cube tower at x = 0.4 m and a 4-step staircase on the left

.PHONY: run test lint bench suite clean

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	@rm -f $(VENV)/.installed-* && touch $(STAMP)

run: $(STAMP)
	$(VENV)/bin/sdi plan "$(DEMO)"

test: $(STAMP)
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/mypy
	$(PY) -m pytest

bench: $(STAMP)
	$(PY) benchmarks/inspector_scaling.py
	$(PY) benchmarks/plan_latency.py
	$(VENV)/bin/sdi bench --out benchmarks/results/suite_rules.json
	$(PY) benchmarks/cell_motion.py

clean:
	rm -rf $(VENV) .pytest_cache .mypy_cache .ruff_cache
