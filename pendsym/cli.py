"""The ``pendsym`` command: list, derive, check, scene.

Exit codes: 0 success; 1 a check failed (``check``, ``derive``); 2 bad input (an unknown id or
memoir, a bad argument, an unwritable output, a corrupt results.json), reported in one line on
stderr, never a traceback; 130 interrupted (Ctrl-C).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

import sympy as sp
import tqdm

import mpmath as mp

from . import derive as drv
from . import checks, pipeline, registry, scene, stages


class UsageError(Exception):
    """Bad input: reported in one line, exit 2."""


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2
        raise UsageError(message)


def _parser(with_keys: bool = True) -> Parser:
    """The argument parser; the memoir keys in the help need the memoirs imported (with_keys)."""
    keys = ", ".join(registry.memoirs()) if with_keys else "see pendsym list --help"
    p = Parser(prog="pendsym", description="Rebuild and check the classical perturbation theory of the pendulum.",
               epilog="exit codes: 0 success, 1 a check failed, 2 bad input, 130 interrupted")
    sub = p.add_subparsers(dest="cmd", required=True, parser_class=Parser, metavar="{list,derive,check,scene,solve}")
    ls = sub.add_parser("list", help="the Results, with their status", epilog=f"memoir keys: {keys}")
    ls.add_argument("--memoir", help=f"a memoir key ({keys})")
    ls.add_argument("--json", action="store_true", help="JSON output")
    ls.add_argument("--generated", default=None,
                    help="the generated/ directory to read status from (default: the project's)")
    dv = sub.add_parser("derive", help="derive Results (all of them when no id is given, writing generated/)")
    dv.add_argument("ids", nargs="*", help="only these Results and their dependencies (printed, nothing written)")
    dv.add_argument("--out", default=None, help="output directory of a full derive (default: generated)")
    dv.add_argument("--level", choices=("quick", "full"), default=None, help="check level of a full derive")
    dv.add_argument("--json", action="store_true", help="with ids: their records as in generated/results.json")
    sc = sub.add_parser("scene", help="an instrument's period and error budget, or a list of Results, from a scene file (TOML, docs/scenes.md)")
    sc.add_argument("file")
    sc.add_argument("--json", action="store_true", help="JSON output")
    sc.add_argument("--pdf", metavar="OUT.pdf", help="a hardware scene: also a one-page PDF of its budget")
    ck = sub.add_parser("check", help="run one Result's independent verification and print the evidence",
                        epilog="exit codes: 0 the check passed (or there is none), 1 it failed, 2 bad input")
    ck.add_argument("id")
    ck.add_argument("--level", choices=("quick", "full"), default="full")
    ck.add_argument("--json", action="store_true", help="the record as in generated/results.json")
    sv = sub.add_parser("solve", help="solve and verify your own perturbation problem (TOML, docs/solve.md)")
    sv.add_argument("file")
    sv.add_argument("--no-verify", action="store_true", help="skip the verification by integration (said in the output)")
    sv.add_argument("--emit", metavar="DIR", help="write answer.tex, answer.py and answer.c there (accuracy measured)")
    return p


def cmd_solve(args) -> int:
    from . import solve as solver        # SymPy-heavy: imported only for this command
    try:
        sol = solver.solve(solver.load(args.file), verify=not args.no_verify)
    except solver.REFUSALS as exc:
        raise UsageError(str(exc)) from None
    print(sol.report())
    if args.emit:
        from .solve import answer
        try:
            rows = answer.emit(sol, Path(args.emit))
        except (OSError, RuntimeError) as exc:
            raise UsageError(f"cannot emit under {args.emit}: {getattr(exc, 'strerror', None) or exc}") from None
        print(f"wrote answer.tex, answer.py, answer.c under {args.emit}/ (kernels measured: docs/kernel-accuracy.md)")
        print("\n".join(answer.kernels.summary(rows) + [f"  {line}" for line in answer.not_kernels(sol)]))
        over = [k.name for k in rows if k.over]
        if over:
            print(f"KERNELS OVER THE BOUND: {', '.join(over)} (written, marked OVER THE BOUND)", file=sys.stderr)
            return 1
    return 1 if sol.verified is False else 0


def cmd_list(args) -> int:
    memoirs = None
    if args.memoir:
        if args.memoir not in registry.memoirs():
            raise UsageError(f"unknown memoir: {args.memoir} (known: {', '.join(registry.memoirs())})")
        memoirs = [args.memoir]
    specs = registry.all_specs(memoirs)
    known = {}
    path = Path(args.generated or _project_generated()) / "results.json"
    if path.exists():
        try:
            known = pipeline.load_results_json(path)
        except (ValueError, KeyError, TypeError, OSError) as exc:
            raise UsageError(f"{path} is not a results.json pendsym can read ({type(exc).__name__})") from None
    rows = []
    for sid, spec in specs.items():
        rec = known.get(sid, {})
        rows.append({"id": sid, "memoir": spec.memoir, "ref": spec.source.ref(), "title": spec.title,
                     "definition": spec.definition,
                     "status": rec.get("status", "not derived"), "verified": rec.get("verified", False)})
    if args.json:
        print(json.dumps(rows, indent=1, ensure_ascii=False))
    else:
        for r in rows:
            mark = "verified" if r["verified"] else "unverified"
            print(f"{r['id']:<44} {r['status']:<13} {mark:<10} {r['ref']}")
    return 0


def _progress():
    """(tick(done, total), close): a progress bar on a terminal, a plain line every 30 s otherwise."""
    if sys.stderr.isatty():
        bar = tqdm.tqdm(total=0, desc="checking", unit="result", file=sys.stderr, leave=False)

        def tick(done: int, total: int) -> None:
            bar.total = total
            bar.update(done - bar.n)
        return tick, bar.close
    last = [-math.inf]

    def plain(done: int, total: int) -> None:
        now = time.monotonic()
        if now - last[0] >= 30 or done == total:       # the first one at once, then every 30 s, and the last
            print(f"checking: {done}/{total} results done, {total - done} to go", file=sys.stderr, flush=True)
            last[0] = now
    return plain, lambda: None


def _forms(result, status: str) -> list[str]:
    """The printed form, the derived one in the printed form's shape where SymPy finds it equal (a
    match), and for a discrepancy the term by which they differ."""
    if result.printed is None:
        return [f"  derived: {sp.sstr(result.derived)}"]
    lines = [f"  printed: {sp.sstr(result.printed)}"]
    if status == "match":
        lines.append("  derived: the same (see the comparison above)")
        lines.append(f"           as SymPy writes it: {sp.sstr(result.derived)}")
        return lines
    lines.append(f"  derived: {sp.sstr(result.derived)}")
    try:
        if not isinstance(result.derived, sp.Tuple):
            diff = sp.factor(sp.simplify(result.derived_value - result.printed_value))
            lines.append(f"  derived − printed: {sp.sstr(diff)}")
    except (TypeError, ValueError, NotImplementedError):
        pass
    return lines


def _project_generated() -> Path:
    """generated/ of the project this pendsym belongs to (the current directory's otherwise)."""
    root = Path(__file__).resolve().parents[1]
    return root / "generated" if (root / "pyproject.toml").exists() else Path("generated")


def cmd_derive(args) -> int:
    if args.json and not args.ids:
        raise UsageError("--json goes with ids (a full derive writes generated/results.json)")
    if args.ids and (args.out is not None or args.level is not None):
        raise UsageError("--out and --level apply to a full derive (no ids); derive ID only prints the forms")
    args.out = args.out or "generated"
    args.level = args.level or "full"
    if args.ids:
        built = registry.build(args.ids)
        records = stages.assess(built.values(), run_checks=False)
        if args.json:
            print(json.dumps([pipeline.record_json(rec) for rec in records], indent=1, ensure_ascii=False))
            return 0
        for rec in records:
            print(f"{rec.result.id}: {rec.status}")
            for line in _forms(rec.result, rec.status):
                print(line)
        return 0
    tick, done = _progress()
    try:
        outcome = drv.derive_all(Path(args.out), level=args.level, log=lambda m: print(m, file=sys.stderr),
                                 progress=tick)
    finally:
        done()
    for line in outcome.summary:
        print(line)
    from .scenes import index as scene_index
    scene_index.remember()    # the tree's index of Results, which `pendsym scene` reads without importing a memoir
    if not outcome.nothing_changed:
        print(f"wrote {len(outcome.written)} files under {args.out}/")
    return 1 if outcome.failed else 0


def cmd_check(args) -> int:
    spec = registry.all_specs([registry.memoir_of(args.id)]).get(args.id)
    if spec is None:
        raise registry.UnknownResult(args.id, registry.all_specs())
    downstream = spec.check.downstream if isinstance(spec.check, checks.Chain) else ()
    # the forms as make derive built them (from the cache under their content keys, built and stored when
    # missing): rebuilding a closure of a few dozen Results from scratch cost 10 s; the check itself runs anew
    built = stages.results([args.id, *downstream], level=args.level)
    r = built[args.id]
    status, how = pipeline.compare(r)
    ev = pipeline.check(r, args.level)
    if downstream:
        evs = {d: pipeline.check(built[d], args.level) for d in downstream}
        ev = checks.chained(spec.check, evs)
    if args.json:
        print(json.dumps(pipeline.record_json(pipeline.Record(r, status, how, ev)), indent=1, ensure_ascii=False))
        return 0 if ev is None or ev.passed else 1
    print(f"{r.id} ({r.spec.source.ref()}): {r.spec.title}")
    print(f"  status: {status} ({how})")
    for line in _forms(r, status):
        print(line)
    if ev is None:
        print("  no independent check")
        return 0
    print(f"  check: {'passed' if ev.passed else 'FAILED'} [{ev.kind}] truth: {ev.truth}")
    if ev.params:
        print("  parameters: " + ", ".join(f"{k} = {v}" for k, v in ev.params))
    print(f"  largest residual: {ev.max_residual}")
    if ev.kind == "order":
        print(f"  fitted order in {ev.param}: {ev.order} (expected {ev.expected_order}, band {ev.band})")
        for p, v in ev.series:
            print(f"    {ev.param} = {p:<12g} |residual| = {v:.6g}")
        if ev.printed_order is not None:
            print(f"  printed form: fitted order {ev.printed_order}")
        print(f"  truth confirmed to {ev.confirm_digits} digits at two precisions")
    if ev.note:
        print(f"  note: {ev.note}")
    return 0 if ev.passed else 1


def cmd_scene(args) -> int:
    data = scene.parse(args.file)
    if scene.is_hardware(data):          # an instrument described as hardware: pendsym.scenes
        from . import scenes
        text = scenes.report(args.file, args.json, data)
        if args.pdf:
            print(f"wrote {scenes.pdf(args.file, args.pdf, data)}", file=sys.stderr)
        print(text)
        return 0
    if args.pdf:
        raise UsageError("--pdf is for a hardware scene (bob, suspension…), not a list of Results")
    sc = scene.load(args.file, data)
    rows, n_built = scene.evaluate(sc)
    if args.json:
        print(json.dumps({"scene": sc.name, "results_built": n_built,
                          "values": [{"id": i, "title": t, "value": float(v)} for i, t, v in rows]}, indent=1))
        return 0
    print(f"{scene.printable(sc.name)}  ({n_built} results built: the closure of {len(sc.results)})")
    for rid, title, val in rows:
        print(f"  {rid:<36} {mp.nstr(val, 8):>16}   {title}")
    return 0


def _fixed_hash_seed() -> None:
    """Run the program under Python's string-hash seed 0: some SymPy results (the order of terms an
    integral comes back in) follow the order of sets of strings, so a derive is byte-reproducible
    only under one seed.  Re-executes the same command when the seed is not 0."""
    if os.environ.get("PYTHONHASHSEED") != "0":
        os.environ["PYTHONHASHSEED"] = "0"
        os.execv(sys.executable, [sys.executable, "-m", "pendsym.cli", *sys.argv[1:]])


def main(argv=None) -> int:
    if argv is None:
        _fixed_hash_seed()
    argv = sys.argv[1:] if argv is None else argv
    try:
        if not argv:
            _parser().print_help()
            return 0
        asks_help = any(a in ("-h", "--help") for a in argv)
        args = _parser(with_keys=asks_help).parse_args(argv)
        return {"list": cmd_list, "derive": cmd_derive, "check": cmd_check, "scene": cmd_scene,
                "solve": cmd_solve}[args.cmd](args)
    except (UsageError, registry.UnknownResult, scene.SceneError, stages.OutputError) as exc:
        print(f"pendsym: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("pendsym: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader went away (pendsym list | head): not an error of ours; silence the final flush
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


if __name__ == "__main__":
    sys.exit(main())
