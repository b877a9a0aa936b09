"""Execution settings: pyproject's [tool.textbook], overridden by TEXTBOOK_* variables,
with bad values named."""
from __future__ import annotations

import pytest
from textbook import __main__ as textbook_cli
from textbook import settings


def write(tmp_path, table: str):
    path = tmp_path / 'pyproject.toml'
    path.write_text(f'[tool.textbook]\n{table}\n')
    return path


def test_pyproject_values_are_read(tmp_path):
    loaded = settings.load(write(tmp_path, 'cell_timeout = 60\njobs = 1\nfresh = true\n'
                                           'test_workers = 4'), {})
    assert (loaded.cell_timeout, loaded.jobs, loaded.fresh, loaded.test_workers) == \
        (60, 1, True, 4)


def test_missing_values_take_the_defaults(tmp_path):
    assert settings.load(write(tmp_path, ''), {}) == settings.Settings()


def test_an_environment_variable_overrides_the_file(tmp_path):
    path = write(tmp_path, 'jobs = 2')
    loaded = settings.load(path, {'TEXTBOOK_JOBS': '1', 'TEXTBOOK_FRESH': '1'})
    assert (loaded.jobs, loaded.fresh) == (1, True)


def test_a_bad_variable_is_named(tmp_path):
    with pytest.raises(ValueError,
                       match="TEXTBOOK_CELL_TIMEOUT: expected a whole number, got 'soon'"):
        settings.load(write(tmp_path, ''), {'TEXTBOOK_CELL_TIMEOUT': 'soon'})


def test_a_bad_file_value_names_the_file_and_setting(tmp_path):
    path = write(tmp_path, 'jobs = 0')
    with pytest.raises(ValueError, match=r'\[tool.textbook\] jobs: expected at least 1, got 0'):
        settings.load(path, {})


def test_an_unknown_setting_is_refused(tmp_path):
    with pytest.raises(ValueError, match='unknown setting.*timeout_s'):
        settings.load(write(tmp_path, 'timeout_s = 3'), {})


def test_the_repository_settings_load():
    assert settings.load().cell_timeout >= 1



@pytest.mark.parametrize('argv, environ, workers, passed_on', [
    (['test'], {}, None, []),
    (['test'], {'TEXTBOOK_TEST_WORKERS': '3'}, '3', []),
    (['test', '-n', '1', '-k', 'tabs'], {'TEXTBOOK_TEST_WORKERS': '3'}, '1', ['-k', 'tabs'])])
def test_make_test_runs_pytest_with_the_configured_workers(monkeypatch, argv, environ, workers,
                                                           passed_on):
    monkeypatch.delenv('TEXTBOOK_TEST_WORKERS', raising=False)
    for name, value in environ.items():
        monkeypatch.setenv(name, value)
    calls = []
    monkeypatch.setattr(textbook_cli, '_exec', lambda *args: calls.append(args) or 0)
    assert textbook_cli.main(argv) == 0
    (args,) = calls
    assert args[0] == 'pytest'
    assert args[args.index('-n') + 1] == (workers or str(settings.load().test_workers))
    assert args[args.index('--dist') + 1] == 'loadgroup' and '--durations=25' in args
    assert list(args[args.index('--durations=25') + 1:]) == passed_on
