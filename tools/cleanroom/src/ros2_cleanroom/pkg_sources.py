"""The manifest, Python and C++ files `ros2 pkg create` writes, in Jazzy's text.

Values are written as given, unescaped (a `<` in a description stays a `<` in
package.xml, a `'` breaks setup.py), as Jazzy writes them.
"""
from __future__ import annotations

from pathlib import Path

TEMPLATES = Path(__file__).with_name('pkg_templates')

#: The licenses whose text `ros2 pkg create` writes to LICENSE, in Jazzy's order.
LICENSES = ('Apache-2.0', 'BSL-1.0', 'BSD-2.0', 'BSD-2-Clause', 'BSD-3-Clause',
            'GPL-3.0-only', 'LGPL-3.0-only', 'MIT', 'MIT-0')

_TEST_DEPENDS = {
    'ament_cmake': ('ament_lint_auto', 'ament_lint_common'),
    'ament_python': ('ament_copyright', 'ament_flake8', 'ament_pep257', 'python3-pytest'),
    'cmake': (),
}


def template(name: str) -> str:
    return (TEMPLATES / name).read_text(encoding='utf-8')


def license_text(license_id: str) -> str:
    return template(f'licenses/{license_id}')


def package_xml(package: str, package_format: int, description: str, maintainer: str,
                email: str, license_name: str, build_type: str, dependencies: list[str],
                library: str | None) -> str:
    text = (
        '<?xml version="1.0"?>\n'
        f'<?xml-model href="http://download.ros.org/schema/package_format{package_format}.xsd" '
        'schematypens="http://www.w3.org/2001/XMLSchema"?>\n'
        f'<package format="{package_format}">\n'
        f'  <name>{package}</name>\n'
        '  <version>0.0.0</version>\n'
        f'  <description>{description}</description>\n'
        f'  <maintainer email="{email}">{maintainer}</maintainer>\n'
        f'  <license>{license_name}</license>\n\n')
    if build_type == 'ament_cmake':
        tool = 'ament_cmake_ros' if library else 'ament_cmake'
        text += f'  <buildtool_depend>{tool}</buildtool_depend>\n\n'
    if dependencies:
        text += ''.join(f'  <depend>{name}</depend>\n' for name in dependencies) + '\n'
    tests = _TEST_DEPENDS[build_type]
    if tests:
        text += ''.join(f'  <test_depend>{name}</test_depend>\n' for name in tests) + '\n'
    return text + (f'  <export>\n    <build_type>{build_type}</build_type>\n  </export>\n'
                   '</package>\n')


def setup_py(package: str, maintainer: str, email: str, description: str,
             license_name: str, node: str | None) -> str:
    scripts = f"            '{node} = {package}.{node}:main'\n" if node else ''
    return (
        'from setuptools import find_packages, setup\n\n'
        f"package_name = '{package}'\n\n"
        'setup(\n'
        '    name=package_name,\n'
        "    version='0.0.0',\n"
        "    packages=find_packages(exclude=['test']),\n"
        '    data_files=[\n'
        "        ('share/ament_index/resource_index/packages',\n"
        "            ['resource/' + package_name]),\n"
        "        ('share/' + package_name, ['package.xml']),\n"
        '    ],\n'
        "    install_requires=['setuptools'],\n"
        '    zip_safe=True,\n'
        f"    maintainer='{maintainer}',\n"
        f"    maintainer_email='{email}',\n"
        f"    description='{description}',\n"
        f"    license='{license_name}',\n"
        "    tests_require=['pytest'],\n"
        '    entry_points={\n'
        "        'console_scripts': [\n"
        f'{scripts}'
        '        ],\n'
        '    },\n'
        ')\n')


def setup_cfg(package: str) -> str:
    return (f'[develop]\nscript_dir=$base/lib/{package}\n'
            f'[install]\ninstall_scripts=$base/lib/{package}\n')


def python_node(package: str) -> str:
    return (f"def main():\n    print('Hi from {package}.')\n\n\n"
            "if __name__ == '__main__':\n    main()\n")


def cpp_node(package: str) -> str:
    return ('#include <cstdio>\n\nint main(int argc, char ** argv)\n{\n'
            '  (void) argc;\n  (void) argv;\n\n'
            f'  printf("hello world {package} package\\n");\n  return 0;\n}}\n')


def class_name(library: str) -> str:
    """The library's C++ class: `my_lib` -> `MyLib`, `HTTPServer` -> `Httpserver`."""
    return library.title().replace('_', '')


def library_header(package: str, library: str) -> str:
    guard = f'{package}__{library}_HPP_'.upper()
    name = class_name(library)
    return (f'#ifndef {guard}\n#define {guard}\n\n'
            f'#include "{package}/visibility_control.h"\n\n'
            f'namespace {package}\n{{\n\n'
            f'class {name}\n{{\npublic:\n  {name}();\n\n  virtual ~{name}();\n}};\n\n'
            f'}}  // namespace {package}\n\n#endif  // {guard}\n')


def library_source(package: str, library: str) -> str:
    name = class_name(library)
    return (f'#include "{package}/{library}.hpp"\n\n'
            f'namespace {package}\n{{\n\n'
            f'{name}::{name}()\n{{\n}}\n\n'
            f'{name}::~{name}()\n{{\n}}\n\n'
            f'}}  // namespace {package}\n')


def visibility_control(package: str) -> str:
    return template('visibility_control.h.tmpl').replace('@PACKAGE_UPPER@', package.upper())
