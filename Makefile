# rpg: quick start is `make demo` (main job) and `make test` (tests); both install first.
VENV ?= .venv
PY := $(VENV)/bin/python
RPG := $(VENV)/bin/rpg
export MUJOCO_GL ?= egl
export LITELLM_LOCAL_MODEL_COST_MAP := True
DEMO_INSTRUCTION ?= Make a simple 2-block tower with a red block on bottom and blue on top

.PHONY: install demo test bench lint clean baseline

install: $(VENV)/.installed

$(VENV)/.installed: pyproject.toml
	@# The sandbox's namespace layer is Debian's bubblewrap: installed here where we can (root
	@# with apt-get); otherwise rpg runs with its other layers and `rpg doctor` says how to add it.
	@command -v bwrap >/dev/null || { [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null && \
	  { apt-get install -y -q bubblewrap >/dev/null 2>&1 || { apt-get update -q >/dev/null 2>&1 && \
	    apt-get install -y -q bubblewrap >/dev/null 2>&1; }; }; } || \
	  echo "note: bubblewrap (bwrap) is not installed; the sandbox runs without its namespace layer." \
	       "Install Debian's 'bubblewrap' package (sudo apt-get install bubblewrap) to add it."
	@# The page tests load the gallery and evaluation pages in Debian's chromium: installed here the
	@# same way; where it cannot be, those tests skip and say so.
	@command -v chromium >/dev/null || { [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null && \
	  { apt-get install -y -q chromium >/dev/null 2>&1 || { apt-get update -q >/dev/null 2>&1 && \
	    apt-get install -y -q chromium >/dev/null 2>&1; }; }; } || \
	  echo "note: chromium is not installed; the page tests skip." \
	       "Install Debian's 'chromium' package (sudo apt-get install chromium) to run them."
	test -x $(PY) || python3 -m venv $(VENV)
	@# Bytecode is written by compileall on every core, not by pip one file at a time (where PYTHONDONTWRITEBYTECODE
	@# is set no process writes it later; a few packages ship files that are not Python 3, as pip ignores them here).
	$(PY) -m pip install -q --no-compile -e '.[dev,ray,baseline]'
	$(PY) -m compileall -q -j 0 $(VENV)/lib >/dev/null || true
	touch $@

demo: install
	$(RPG) compile "$(DEMO_INSTRUCTION)" -o out

# One xdist worker more than the machine has cores: the suite waits on subprocesses, sandboxed children
# and Ray (a fresh clone on 2 cores: 1216 s with 2 workers, 1137 s with 3; measured in the fiftieth session).
TEST_WORKERS ?= $(shell echo $$(( $$(nproc) + 1 )))

# Where PYTHONDONTWRITEBYTECODE is set (this machine sets it), no process writes bytecode and each one compiled
# rpg's modules again (the language lexicon's among them: `import rpg.compiler` 1.7 -> 1.1 s with it written once).
test: install
	$(PY) -m compileall -q src >/dev/null
	$(PY) -m pytest -n $(TEST_WORKERS) -q

bench: install
	$(PY) benchmarks/bench_domain.py
	$(PY) benchmarks/bench_compile.py
	$(PY) benchmarks/bench_library.py
	$(PY) benchmarks/bench_env.py
	$(PY) benchmarks/bench_oracle.py
	$(PY) benchmarks/bench_eval.py

baseline: install
	@# examples/baseline: oracle demos of the training split -> BC training -> rpg eval of the baseline,
	@# the oracle and random on the training, steered and evaluation tasks -> build/baseline/results.md
	nice -n 10 $(PY) examples/baseline/run.py --out build/baseline

lint: install
	$(VENV)/bin/ruff check src tests benchmarks examples

clean:
	rm -rf out .pytest_cache
