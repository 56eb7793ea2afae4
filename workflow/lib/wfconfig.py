"""The workflow's configuration: one declaration, resolved and checked before any job runs.

The declaration is the workflow's own settings (:data:`WORKFLOW`) plus one group per study of
:data:`gearrep.replications.REGISTRY`, made from the study's ``SETTINGS``. ``config/config.yaml``
(and any ``--configfile`` such as ``config/test.yaml``) only override declared values;
``config/schema.json`` is generated from the declaration (``python workflow/lib/wfconfig.py
--write-schema``) and a test keeps it equal to it. It is JSON, not YAML: Snakemake's ``validate``
reads a schema file as JSON first, in about a millisecond, where the same schema as YAML took
0.27 s of every workflow start (its YAML reader is pure Python).

Run as a script, it writes the schema or prints the settings table.
"""

from __future__ import annotations

import sys
from pathlib import Path

from gearrep import settings as S
from gearrep.replications import REGISTRY, load

__all__ = ["WORKFLOW", "declaration", "resolve_config", "validate_studies", "schema", "SCHEMA_COMMENT"]

#: the workflow's own settings (the studies' settings come from their packages)
WORKFLOW = S.declare(
    published_dir=S.text("data/published", "directory of the digitised published data (relative to the workflow)"),
    bench=S.group(
        "sizes of the benchmark target `snakemake bench` (not part of the default run)",
        n_vectorised=S.integer(10000, "count", "points per vectorised solve call", ge=10, le=1_000_000),
        n_single=S.integer(200, "count", "points solved one call each", ge=1, le=100_000),
        repeats=S.integer(5, "count", "timings are medians of this many runs", ge=1, le=100),
        replications=S.array(
            list(REGISTRY),
            "",
            "studies whose bench_cases() the bench target sweeps",
            S.choice(None, list(REGISTRY), ""),
            min_items=0,
        ),
    ),
)


def declaration() -> dict:
    """The whole configuration's declaration: workflow settings and one group per study."""
    out = dict(WORKFLOW)
    for key, study in REGISTRY.items():
        out[key] = S.group(
            f"seed {study.seed}, {study.document}: {study.scope} (gearrep.replications.{key})", **load(key).SETTINGS
        )
    return out


def resolve_config(config: dict, root: Path | str = ".") -> dict:
    """Every declared setting resolved with ``config`` (unknown sections and keys refused with the
    closest declared name; ranges, NaN and infinity checked); the published-data directory must
    exist. Raises ``SettingError`` naming the key before any job runs."""
    resolved = S.resolve(declaration(), config, where="config")
    d = Path(root, resolved["published_dir"])
    if not d.is_dir():
        raise S.SettingError(f"config.published_dir: {resolved['published_dir']!r} is not a directory under {root}")
    return resolved


def validate_studies(resolved: dict, root: Path | str = ".") -> None:
    """Each study's cross-field checks (``validate(settings, design)``: limits between settings,
    names that must exist in the design data) with its published design data, before any job."""
    from gearrep import published

    d = Path(root, resolved["published_dir"])
    for key in REGISTRY:
        study = load(key)
        design = study.params_from_published(published.load(d, study.DESIGN_DATA))
        study.validate(resolved[key], design)


#: the schema file's ``$comment`` (JSON has no comments)
SCHEMA_COMMENT = (
    "GENERATED from the settings declarations (gearrep.replications.<study>.SETTINGS and "
    "workflow/lib/wfconfig.py): do not edit; regenerate with `make schema`."
)


def schema() -> dict:
    """JSON schema of the configuration (every key optional: the declaration holds the values)."""
    out = {"$schema": "https://json-schema.org/draft/2020-12/schema", "$comment": SCHEMA_COMMENT}
    out.update(S.json_schema(declaration(), "gearrep workflow configuration"))
    return out


def _main(argv):
    if argv[:1] == ["--write-schema"]:
        import json

        path = Path(argv[1] if len(argv) > 1 else "config/schema.json")
        path.write_text(json.dumps(schema(), indent=2, allow_nan=False) + "\n")
        print(f"wrote {path}")
    else:
        for section, decl in declaration().items():
            for row in S.rows({section: decl}):
                print(f"{row['name']}\t{row['value']}\t{row['unit']}\t{row['allowed']}\t{row['reason']}")


if __name__ == "__main__":
    _main(sys.argv[1:])
