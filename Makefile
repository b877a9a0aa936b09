# The two commands a newcomer needs are `make serve` and `make test`;
# both set up the project environment first (see tools/setup_env.sh).
PY := .venv/bin/python

.PHONY: setup serve site test check lint lab lock clean

setup:
	@bash tools/setup_env.sh

serve: setup
	$(PY) -m textbook serve

site: setup
	$(PY) -m textbook build

test: setup
	$(PY) -m textbook test

# The quick tier, for every change: lint, the lessons' static checks and the
# unit tests (with the import contracts); `make test` runs every tier.
check: setup
	$(PY) -m ruff check .
	$(PY) -m textbook check
	$(PY) -m textbook test -m unit

lint: setup
	$(PY) -m ruff check .

# JupyterLab on lessons/ in the book's kernel (README: "Teaching from the
# notebooks"); LAB_FLAGS=--no-browser in a container or over ssh.
lab: setup
	$(PY) -m textbook lab $(LAB_FLAGS)

# The lock is resolved from base.in by pip-tools (pip's resolver, pip's index
# settings), not frozen from an environment: every pin is a distribution that
# something asks for.  Existing pins are kept unless LOCK_FLAGS=--upgrade.
lock:
	rm -rf build/lockenv && python3 -m venv build/lockenv
	build/lockenv/bin/pip install -q pip-tools==7.6.2
	build/lockenv/bin/pip-compile -q --strip-extras --no-emit-index-url --no-emit-find-links \
		$(LOCK_FLAGS) --output-file requirements/lock.txt requirements/base.in

clean:
	rm -rf build site
