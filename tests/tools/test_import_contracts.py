"""The import contract (.importlinter): no import cycles in launch, launch_ros, labkit & co.

A cycle makes one module run while another is half imported, where
`from package import name` can give a module instead of a function (issue 13).
"""
from __future__ import annotations

import ast
import configparser
import importlib.util
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CONFIG = ROOT / '.importlinter'
LINT_IMPORTS = Path(sys.executable).parent / 'lint-imports'


def test_import_contract_is_kept():
    result = subprocess.run([str(LINT_IMPORTS), '--no-cache', '--no-logo', '--config', str(CONFIG)],
                            cwd=ROOT, capture_output=True, text=True, check=False)
    assert result.returncode == 0, (
        f'lint-imports found a broken import contract (exit {result.returncode}):\n'
        f'{result.stdout}{result.stderr}')


def ignored_imports() -> set[tuple[str, str]]:
    """The (importer, imported) pairs any contract of .importlinter ignores."""
    parser = configparser.ConfigParser()
    parser.read(CONFIG)
    pairs = set()
    for section in parser.sections():
        for line in parser[section].get('ignore_imports', '').splitlines():
            line = line.split('#', 1)[0].strip()
            if line:
                importer, imported = (part.strip() for part in line.split('->'))
                pairs.add((importer, imported))
    return pairs


def imports_of(module: str, tree: ast.Module) -> list[tuple[str, bool]]:
    """(imported module, True when imported only inside a function) for each import."""
    package = module if module_is_package(module) else module.rpartition('.')[0]
    found = []

    def visit(node: ast.AST, late: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.ImportFrom):
                base = importlib.util.resolve_name('.' * child.level + (child.module or ''),
                                                   package) if child.level else child.module
                found.extend([(base, late)] + [(f'{base}.{a.name}', late) for a in child.names])
            elif isinstance(child, ast.Import):
                found.extend((alias.name, late) for alias in child.names)
            elif isinstance(child, ast.If) and ast.unparse(child.test) == 'TYPE_CHECKING':
                continue  # never run, so no cycle at run time
            visit(child, late or isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)))

    visit(tree, False)
    return found


def module_is_package(module: str) -> bool:
    spec = importlib.util.find_spec(module)
    return spec is not None and spec.submodule_search_locations is not None


def test_ignored_imports_stay_inside_functions():
    # An ignored import moved to module level would bring the cycle back at run
    # time while lint-imports (which ignores it) still passes.
    pairs = ignored_imports()
    assert pairs, f'no ignore_imports found in {CONFIG}'
    for importer, imported in sorted(pairs):
        spec = importlib.util.find_spec(importer)
        assert spec is not None and spec.origin, f'{importer} (ignore_imports) not found'
        tree = ast.parse(Path(spec.origin).read_text(), spec.origin)
        matching = [late for name, late in imports_of(importer, tree)
                    if name == imported or name.startswith(imported + '.')]
        assert matching, f'{importer} no longer imports {imported}: drop it from ignore_imports'
        assert all(matching), (f'{spec.origin} imports {imported} at module level: that is '
                               f'an import cycle; keep the import inside the function')
