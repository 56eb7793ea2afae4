"""Reading the inputs of the ``gearrep`` command: YAML files and the refusal of a bad input."""

from __future__ import annotations

import re
from pathlib import Path

import yaml

__all__ = ["Refusal", "load_yaml"]


class Refusal(Exception):
    """A refused input (file, option or design): the message names it; exit code 2."""


def load_yaml(path) -> object:
    """The YAML document of ``path``: floats like ``1e-3`` read as numbers (YAML 1.2), repeated
    keys refused. Raises Refusal naming the file (and line) on any problem."""

    class Loader(yaml.SafeLoader):
        pass

    Loader.add_implicit_resolver(
        "tag:yaml.org,2002:float",
        re.compile(
            r"""^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+]?[0-9]+)?|[-+]?(?:[0-9][0-9_]*)(?:[eE][-+]?[0-9]+)
            |\.[0-9_]+(?:[eE][-+]?[0-9]+)?|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$""",
            re.X,
        ),
        list("-+0123456789."),
    )

    def mapping(loader, node):
        loader.flatten_mapping(node)
        out = {}
        for kn, vn in node.value:
            k = loader.construct_object(kn, deep=True)
            if not isinstance(k, (str, int, float, bool)) and k is not None:
                raise Refusal(f"{path}: line {kn.start_mark.line + 1}: key {k!r} is not a plain key")
            if k in out:
                raise Refusal(f"{path}: line {kn.start_mark.line + 1}: key {k!r} repeated; allowed: each key once")
            out[k] = loader.construct_object(vn, deep=True)
        return out

    Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, mapping)
    p = Path(path)
    try:
        text = p.read_text()
    except (OSError, UnicodeDecodeError) as e:
        raise Refusal(
            f"{path}: cannot read ({e.__class__.__name__}: {e}); allowed: a readable UTF-8 YAML file"
        ) from None
    try:
        return yaml.load(text, Loader=Loader)
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f" line {mark.line + 1}" if mark is not None else ""
        raise Refusal(f"{path}:{where} not valid YAML ({getattr(e, 'problem', None) or e})") from None
    except RecursionError:
        raise Refusal(f"{path}: nested too deeply; allowed: a design mapping (see the schema)") from None
