"""The `$(name args)` parser used by ParameterFile(allow_substs=True)."""
import pytest
from launch_ros.utilities.substitution_text import SubstitutionSyntaxError, expand_substitutions


def resolve(name, args):
    return '<{}:{}>'.format(name, '|'.join(args))


def test_plain_text_untouched():
    assert expand_substitutions('a: 1\nb: $x (y)', resolve) == 'a: 1\nb: $x (y)'


def test_var_nested_and_quoted():
    text = 'r: $(var robot)\np: $(find-pkg-share $(var pkg))/c\ne: $(env X "a b")'
    assert expand_substitutions(text, resolve) == (
        'r: <var:robot>\np: <find-pkg-share:<var:pkg>>/c\ne: <env:X|a b>')


@pytest.mark.parametrize('text', ['x: $(var robot', 'x: $()', "x: $(env 'a)"])
def test_syntax_errors_name_the_text(text):
    with pytest.raises(SubstitutionSyntaxError, match='in '):
        expand_substitutions(text, resolve)
