#!/usr/bin/env python3
"""Checks USDZ files with Pixar's usd-core (PyPI `usd-core`).

Usage: python scripts/usd-check.py FILE.usdz...

For each file: opens it as a stage, runs every validator usd-core
registers (`UsdValidation.ValidationRegistry().GetOrLoadAllValidators()`:
the stage-metadata, material-binding, encapsulation and shader checks and
the usdz package checks `RootPackageValidator` / `UsdzPackageValidator`
for stored, 64-byte-aligned entries), and counts the triangles of every
Mesh prim, instance proxies included (an instanced prototype counts once
per instance, as a renderer draws it).

Prints one JSON line per file: {"file", "ok", "errors": [..],
"warnings": [..], "triangles", "meshes", "instances", "stage": {the
default prim, metersPerUnit, upAxis, customLayerData}}. "ok" is false
when the stage does not open or any validator reports an error. Exits 1
if any file is not ok, 2 if usd-core is missing (scripts/test installs it
into .tools/venv)."""
import json
import sys

try:
    from pxr import Usd, UsdGeom, UsdValidation
except ImportError as e:  # a missing checker must fail, never skip
    print(f"usd-check: usd-core is not installed: {e}", file=sys.stderr)
    sys.exit(2)


def check(path, context):
    report = {"file": path, "ok": False}
    stage = Usd.Stage.Open(path)
    if stage is None:
        report["errors"] = ["the stage does not open"]
        return report
    errors, warnings = [], []
    for e in context.Validate(stage):
        v = e.GetValidator()
        text = f"{v.GetMetadata().name if v else '?'}: {e.GetMessage()}"
        if e.GetType() == UsdValidation.ValidationErrorType.Error:
            errors.append(text)
        else:
            warnings.append(text)
    triangles = meshes = instances = 0
    for prim in Usd.PrimRange(stage.GetPseudoRoot(), Usd.TraverseInstanceProxies()):
        if prim.IsInstance():
            instances += 1
        if prim.IsA(UsdGeom.Mesh):
            meshes += 1
            counts = UsdGeom.Mesh(prim).GetFaceVertexCountsAttr().Get() or []
            triangles += sum(n - 2 for n in counts)
    default = stage.GetDefaultPrim()
    report.update(
        ok=not errors,
        errors=errors,
        warnings=warnings,
        triangles=triangles,
        meshes=meshes,
        instances=instances,
        stage={
            "defaultPrim": default.GetName() if default else None,
            "metersPerUnit": UsdGeom.GetStageMetersPerUnit(stage),
            "upAxis": str(UsdGeom.GetStageUpAxis(stage)),
            "customLayerData": stage.GetRootLayer().customLayerData,
        },
    )
    return report


def main(paths):
    validators = UsdValidation.ValidationRegistry().GetOrLoadAllValidators()
    context = UsdValidation.ValidationContext(validators)
    failed = 0
    for path in paths:
        report = check(path, context)
        failed += not report["ok"]
        print(json.dumps(report, default=str), flush=True)
    print(f"usd-check: {len(paths) - failed} passed, {failed} failed ({len(validators)} validators)", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
