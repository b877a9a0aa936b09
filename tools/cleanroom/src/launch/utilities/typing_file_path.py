"""`FilePath`: what launch accepts as a file's path (Jazzy's `launch.utilities.typing_file_path`).

Kept in its own module because Jazzy's front-end `Parser.load` is annotated
with it (`Union[~FilePath, TextIO]`) and the YAML parser imports it from here.
"""
import os
import typing

FilePath = typing.TypeVar('FilePath', str, bytes, os.PathLike)
