"""schemathesis hooks for tests/it/harden/schema.rs (SCHEMATHESIS_HOOKS=rulemesh_hooks).

One check: a request generated to match the published schema may be refused
with 400 only because of its grammar source (`parse_error`, `eval_error`),
never as a malformed request (`bad_request`): that would mean the schema
allows what the validator refuses (schemathesis's ST202, made strict again
after schemathesis.toml lets 400 through for sources that do not parse).
"""
import json
import os

import schemathesis

# Where each positive case the check sees is counted (one line each), so the
# test can tell the hook ran rather than failed to load.
LOG = os.environ.get("RULEMESH_HOOK_LOG")


@schemathesis.check
def refused_only_for_its_source(ctx, response, case):
    meta = getattr(case, "meta", None)
    if meta is None or not meta.generation.mode.is_positive:
        return None
    if LOG:
        with open(LOG, "a", encoding="utf-8") as f:
            f.write(f"{response.status_code}\n")
    if response.status_code != 400:
        return None
    try:
        code = json.loads(response.content)["error"]["code"]
    except (ValueError, KeyError, TypeError):
        raise AssertionError(f"a 400 without the error body: {response.content[:200]!r}")
    if code not in ("parse_error", "eval_error"):
        raise AssertionError(f"schema-valid request refused as `{code}`: {response.content[:300]!r}")
    return None
