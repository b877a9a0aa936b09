"""The textbook's build: lessons are checked, executed against the snippets
workspace in an isolated ROS domain, cached by content and rendered by mkdocs.

Entry point: ``python -m textbook build|serve|test``.
"""

__version__ = '0.1.0'
