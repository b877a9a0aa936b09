# The two commands a newcomer needs are `make serve` and `make test`;
# both set up the project environment first (see tools/setup_env.sh).
PY := .venv/bin/python

.PHONY: setup serve site test lint lock clean

setup:
	@bash tools/setup_env.sh

serve: setup
	$(PY) -m textbook serve

site: setup
	$(PY) -m textbook build

test: setup
	$(PY) -m textbook test

lint: setup
	$(PY) -m ruff check .

lock:
	rm -rf build/lockenv && python3 -m venv build/lockenv
	build/lockenv/bin/pip install -q -r requirements/base.in
	build/lockenv/bin/pip freeze | grep -v -E '^-e|@ file' > requirements/lock.txt

clean:
	rm -rf build site
