# rpg: quick start is `make demo` (main job) and `make test` (tests); both install first.
VENV ?= .venv
PY := $(VENV)/bin/python
RPG := $(VENV)/bin/rpg
export MUJOCO_GL ?= egl
export LITELLM_LOCAL_MODEL_COST_MAP := True
DEMO_INSTRUCTION ?= Make a simple 2-block tower with a red block on bottom and blue on top

.PHONY: install demo test bench lint clean

install: $(VENV)/.installed

$(VENV)/.installed: pyproject.toml
	test -x $(PY) || python3 -m venv $(VENV)
	$(PY) -m pip install -q -e '.[dev,ray]'
	touch $@

demo: install
	$(RPG) compile "$(DEMO_INSTRUCTION)" -o out

test: install
	$(PY) -m pytest -n auto -q

bench: install
	$(PY) benchmarks/bench_domain.py
	$(PY) benchmarks/bench_compile.py
	$(PY) benchmarks/bench_library.py
	$(PY) benchmarks/bench_env.py
	$(PY) benchmarks/bench_oracle.py
	$(PY) benchmarks/bench_eval.py

lint: install
	$(VENV)/bin/ruff check src tests benchmarks

clean:
	rm -rf out .pytest_cache
