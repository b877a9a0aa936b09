"""The CMake files `ros2 pkg create` writes for the cmake and ament_cmake build types.

Their text, blank lines included, is Jazzy's as observed for every combination
of node, library and dependencies (tests/cli/pkg_create_expected.json).
"""
from __future__ import annotations

from pathlib import Path

TEMPLATES = Path(__file__).with_name('pkg_templates')

_HEAD = """\
cmake_minimum_required(VERSION 3.8)
project({package})
"""
_WARNINGS = """\
if(CMAKE_COMPILER_IS_GNUCXX OR CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  add_compile_options(-Wall -Wextra -Wpedantic)
endif()
"""
_NO_DEPENDENCIES = """\
# uncomment the following section in order to fill in
# further dependencies manually.
# find_package(<dependency> REQUIRED)
"""
_VISIBILITY = """\
# Causes the visibility macros to use dllexport rather than dllimport,
# which is appropriate when building the dll but not consuming it.
target_compile_definitions({library} PRIVATE "{upper}_BUILDING_LIBRARY")
"""
_AMENT_TESTING = """\
if(BUILD_TESTING)
  find_package(ament_lint_auto REQUIRED)
  # the following line skips the linter which checks for copyrights
  # comment the line when a copyright and license is added to all source files
  set(ament_cmake_copyright_FOUND TRUE)
  # the following line skips cpplint (only works in a git repo)
  # comment the line when this package is in a git repo and when
  # a copyright and license is added to all source files
  set(ament_cmake_cpplint_FOUND TRUE)
  ament_lint_auto_find_test_dependencies()
endif()
"""


def _features(target: str) -> str:
    return (f'target_compile_features({target} PUBLIC c_std_99 cxx_std_17)'
            '  # Require C99 and C++17\n')


def _find_packages(dependencies: list[str]) -> str:
    return ''.join(f'find_package({name} REQUIRED)\n' for name in dependencies)


def _ament_dependencies(target: str, dependencies: list[str]) -> str:
    if not dependencies:
        return ''
    quoted = ''.join(f'  "{name}"\n' for name in dependencies)
    return f'ament_target_dependencies(\n  {target}\n{quoted})\n'


def _ament_includes(target: str) -> str:
    return (f'target_include_directories({target} PUBLIC\n'
            '  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>\n'
            '  $<INSTALL_INTERFACE:include/${PROJECT_NAME}>)\n')


def ament_cmake_lists(package: str, dependencies: list[str], node: str | None,
                      library: str | None) -> str:
    """CMakeLists.txt of an ament_cmake package."""
    text = _HEAD.format(package=package) + '\n' + _WARNINGS + '\n'
    text += '# find dependencies\nfind_package(ament_cmake REQUIRED)\n'
    if library:
        text += 'find_package(ament_cmake_ros REQUIRED)\n'
    text += _find_packages(dependencies) if dependencies else _NO_DEPENDENCIES
    text += '\n'
    if library:
        text += (f'add_library({library} src/{library}.cpp)\n'
                 f'add_library({package}::{library} ALIAS {library})\n'
                 + _features(library) + _ament_includes(library)
                 + _ament_dependencies(library, dependencies) + '\n'
                 + _VISIBILITY.format(library=library, upper=package.upper()) + '\n'
                 'install(\n  DIRECTORY include/\n  DESTINATION include/${PROJECT_NAME}\n)\n'
                 f'install(\n  TARGETS {library}\n  EXPORT export_${{PROJECT_NAME}}\n'
                 '  ARCHIVE DESTINATION lib\n  LIBRARY DESTINATION lib\n'
                 '  RUNTIME DESTINATION bin\n)\n\n')
    if node:
        text += f'add_executable({node} src/{node}.cpp)\n' + _ament_includes(node)
        if library:
            text += f'target_link_libraries({node} {library})\n'
        else:
            text += _features(node) + _ament_dependencies(node, dependencies)
        text += f'\ninstall(TARGETS {node}\n  DESTINATION lib/${{PROJECT_NAME}})\n\n'
    text += _AMENT_TESTING + '\n'
    if library:
        text += ('ament_export_include_directories(\n  "include/${PROJECT_NAME}"\n)\n'
                 f'ament_export_libraries(\n  {library}\n)\n'
                 'ament_export_targets(\n  export_${PROJECT_NAME}\n)\n\n')
    return text + 'ament_package()\n'


def _plain_includes(target: str, dependencies: list[str]) -> str:
    extra = ''.join(f'  PUBLIC ${{{name}_INCLUDE_DIRS}}\n' for name in dependencies)
    return (f'target_include_directories({target} PUBLIC\n'
            '  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>\n'
            f'  $<INSTALL_INTERFACE:include>\n{extra})\n')


def _plain_links(target: str, dependencies: list[str]) -> str:
    if not dependencies:
        return ''
    libraries = ''.join(f' ${{{name}_LIBRARIES}}\n' for name in dependencies)
    return f'target_link_libraries({target}\n{libraries})\n'


def _plain_config(package: str, targets: list[str]) -> str:
    sets = ''.join(f'set(export_targets ${{export_targets}};{target})\n' for target in targets)
    binary = '${PROJECT_BINARY_DIR}'
    return (f'\n# export targets\n{sets}'
            f'export(EXPORT export_{package}\n  FILE "{binary}/export_{package}.cmake")\n\n'
            f'# Create the {package}Config.cmake\n'
            'set(CONF_INCLUDE_DIRS "${CMAKE_INSTALL_PREFIX}/include")\n'
            f'configure_file({package}Config.cmake.in\n'
            f'  "{binary}/${{CMAKE_FILES_DIRECTORY}}/{package}Config.cmake" @ONLY)\n\n'
            f'# Create the {package}ConfigVersion.cmake\n'
            f'configure_file({package}ConfigVersion.cmake.in\n'
            f'  "{binary}/{package}ConfigVersion.cmake" @ONLY)\n\n'
            'install(FILES\n'
            f'  "{binary}/${{CMAKE_FILES_DIRECTORY}}/{package}Config.cmake"\n'
            f'  "{binary}/{package}ConfigVersion.cmake"\n'
            '  DESTINATION "share/${PROJECT_NAME}/cmake" COMPONENT dev)\n'
            f'install(EXPORT export_{package}\n'
            '  DESTINATION "share/${PROJECT_NAME}/cmake"\n'
            f'  FILE export_{package}.cmake\n  COMPONENT dev)\n')


def plain_cmake_lists(package: str, dependencies: list[str], node: str | None,
                      library: str | None) -> str:
    """CMakeLists.txt of a plain cmake package (it installs a <package>Config.cmake)."""
    text = _HEAD.format(package=package) + '\n'
    text += ''.join(f'set({package}_{part}_VERSION 0)\n' for part in ('MAJOR', 'MINOR', 'PATCH'))
    text += (f'set({package}_VERSION\n  ${{{package}_MAJOR_VERSION}}.'
             f'${{{package}_MINOR_VERSION}}.${{{package}_PATCH_VERSION}})\n\n')
    text += _WARNINGS + '\n'
    text += ('\n# find dependencies\n' + _find_packages(dependencies)
             if dependencies else _NO_DEPENDENCIES)
    if library:
        text += (f'\nadd_library({library} SHARED src/{library}.cpp)\n'
                 f'add_library({package}::{library} ALIAS {library})\n'
                 + _features(library) + _plain_includes(library, dependencies)
                 + _plain_links(library, dependencies) + '\n'
                 + _VISIBILITY.format(library=library, upper=package.upper()) + '\n'
                 'install(\n  DIRECTORY include/\n  DESTINATION include\n)\n'
                 f'install(\n  TARGETS {library}\n  EXPORT export_{package}\n'
                 '  ARCHIVE DESTINATION lib\n  LIBRARY DESTINATION lib\n'
                 '  RUNTIME DESTINATION bin)\n')
    if node:
        text += f'\nadd_executable({node} src/{node}.cpp)\n'
        if dependencies:
            text += _plain_includes(node, dependencies)
        if library:
            text += f'target_link_libraries({node} {library})\n'
        else:
            text += _features(node) + _plain_links(node, dependencies)
        text += (f'\ninstall(\n  TARGETS {node}\n  EXPORT export_{package}\n'
                 '  DESTINATION lib/${PROJECT_NAME})\n')
    targets = [name for name in (library, node) if name]
    return text + (_plain_config(package, targets) if targets else '')


def config_cmake_in(package: str, node: str | None, library: str | None) -> str:
    """<package>Config.cmake.in of a plain cmake package."""
    text = (f'# - Config file for the {package} package\n'
            '# It defines the following variables\n'
            f'#  {package}_INCLUDE_DIRS - include directories for FooBar\n'
            f'#  {package}_LIBRARIES    - libraries to link against\n'
            f'#  {package}_EXECUTABLE   - the bar executable\n\n'
            f'set({package}_INCLUDE_DIRS "@CONF_INCLUDE_DIRS@")\n\n'
            '# Our library dependencies (contains definitions for IMPORTED targets)\n'
            f'include("${{{package}_DIR}}/export_{package}.cmake")\n\n'
            f'# These are IMPORTED targets created by {package}Targets.cmake\n')
    if library:
        text += f'set({package}_LIBRARIES {library})\n'
    text += '\n'
    if node:
        text += f'set({package}_EXECUTABLE {node})\n'
    return text + '\n'


def config_version_cmake_in(package: str) -> str:
    """<package>ConfigVersion.cmake.in of a plain cmake package."""
    text = (TEMPLATES / 'ConfigVersion.cmake.in.tmpl').read_text(encoding='utf-8')
    return text.replace('@PACKAGE@', package)
