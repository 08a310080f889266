"""The conformance run's results and their markdown report (benchmarks/SINGULAR_TST.md): counts by
folder and category, what blocks the cases mech cannot run, every difference, crash, error and timeout,
the cases set aside and the exclusions."""
from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass

from tst_explained import EXPLAINED, NOT_RUN
from tst_source import FOLDERS, Case

CATEGORIES = ("agree", "differ", "unsupported", "error", "crash", "timeout")


@dataclass
class Result:
    """One case's verdict."""

    name: str
    category: str            # one of CATEGORIES, or "set aside"
    key: str = ""            # unsupported: the blocking construct; error/crash: the message; set aside: why
    detail: str = ""         # the first difference, the source line of the error, ...
    seconds: float = 0.0     # mech's wall time

    @property
    def folder(self) -> str:
        return self.name.split("/", 1)[0]


def report(results: list[Result], excluded: list[Case], meta: dict) -> str:
    """The markdown table: counts by folder and category, exclusions, the ranked missing features and
    every case that differs, crashes, errs or runs out of time."""
    run_ = [r for r in results if r.category in CATEGORIES]
    aside = [r for r in results if r.category == "set aside"]
    lines = [
        "# mech on Singular's own tests",
        "",
        f"Measured {meta['date']} with `{meta['command']}` ({meta['minutes']:.0f} min on the 2-core machine, "
        f"{meta['jobs']} jobs, {meta['timeout']:g} s per statement): expected outputs from live runs of "
        f"{meta['singular']}; test files and library examples of Singular's sources at commit "
        f"`{meta['src_commit']}`; mech at commit `{meta['mech_commit']}`.",
        "",
        "How cases are chosen, run and compared: the docstrings of `benchmarks/singular_tst.py`, "
        "`tst_source.py` (the selection rule), `tst_compare.py` (comparison as values). Agreement counts "
        "equal text, equal values (ideals as ideals, lists of ideals as sets, primary decompositions up to "
        "embedded components, factorizations up to order and units), an error at the same place as "
        "Singular's, and values Singular chooses among many correct ones (`checked`: each of mech's values "
        "proven right by a check Singular runs on it, `tst_checks.py`; listed below with the check).",
        "",
        "## Result",
        "",
        "| folder | cases | out of scope | set aside | run | " + " | ".join(CATEGORIES) + " | agree % |",
        "|---|" + "---|" * (len(CATEGORIES) + 5),
    ]
    folders = [f for f in FOLDERS + ("LIB",) if any(r.folder == f for r in results) or
               any(c.folder == f for c in excluded)] + ["all"]
    for f in folders:
        rs = [r for r in run_ if f in ("all", r.folder)]
        c = Counter(r.category for r in rs)
        n_out = sum(1 for x in excluded if f in ("all", x.folder))
        n_aside = sum(1 for r in aside if f in ("all", r.folder))
        pct = f"{100 * c['agree'] / len(rs):.0f}" if rs else "-"
        label = "LIB (examples)" if f == "LIB" else f
        lines.append(f"| {label} | {len(rs) + n_out + n_aside} | {n_out} | {n_aside} | {len(rs)} | "
                     + " | ".join(str(c[k]) for k in CATEGORIES) + f" | {pct} |")
    kinds = Counter(r.key for r in run_ if r.category == "agree")
    lines += ["", "Agreement: " + ", ".join(f"{n} {k}" for k, n in kinds.most_common()) + "."]
    checked = sorted((r for r in run_ if r.category == "agree" and r.key == "checked"), key=lambda r: r.name)
    lines += ["", f"## Agreement judged by a check Singular runs on mech's values ({len(checked)})", ""]
    lines += [f"- `{r.name}`: {_md(r.detail)}" for r in checked] or ["none"]
    lines += _ranking(run_)
    sections = (("differ", "value", "Differences: other values than Singular's"),
                ("differ", "accepts", "Differences: Singular reports an error, mech goes on"),
                ("crash", None, "Crashes"), ("error", None, "Errors"), ("timeout", None, "Timeouts"))
    for cat, key, title in sections:
        rs = sorted((r for r in run_ if r.category == cat and key in (None, r.key)), key=lambda r: r.name)
        lines += ["", f"## {title} ({len(rs)})", ""]
        shown = (lambda r: r.detail) if key else (lambda r: r.key + (f" — `{r.detail}`" if r.detail else ""))
        why = EXPLAINED if cat == "differ" else NOT_RUN
        lines += [f"- `{r.name}`: {_md(shown(r))}" + (f" — **why:** {why[r.name]}" if r.name in why else "")
                  for r in rs] or ["none"]
    named = sorted((r for r in run_ if r.category == "unsupported" and r.name in NOT_RUN), key=lambda r: r.name)
    lines += ["", f"## Unsupported, looked at: why ({len(named)})", ""]
    lines += [f"- `{r.name}`: {_md(r.key)} — **why:** {NOT_RUN[r.name]}" for r in named] or ["none"]
    lines += ["", "## Set aside", ""]
    for key, n in Counter(r.key for r in aside).most_common():
        names = sorted(r.name for r in aside if r.key == key)
        lines.append(f"- {key} ({n}): " + ", ".join(f"`{x}`" for x in names))
    lines += ["", "## Out of scope (the first out-of-scope construct of each script)", "",
              "| reason | cases |", "|---|---|"]
    reasons = Counter("a library outside the scope" if c.excluded.startswith("library ") else
                      c.excluded.split(": ")[0] for c in excluded)
    for key, n in reasons.most_common():
        lines.append(f"| {key} | {n} |")
    libs = Counter(c.excluded.split(" ", 1)[1] for c in excluded if c.excluded.startswith("library "))
    if libs:
        lines += ["", "Libraries outside the scope (cases): " + ", ".join(f"{k} {n}" for k, n in libs.most_common())
                  + "."]
    return "\n".join(lines) + "\n"


def _ranking(run_: list[Result], top: int = 60) -> list[str]:
    """What stops the cases mech cannot run: the first unsupported construct, error or crash of each,
    ranked by the number of cases."""
    blocked = [r for r in run_ if r.category in ("unsupported", "error", "crash")]
    by_key: dict[tuple[str, str], list[Result]] = defaultdict(list)
    for r in blocked:
        by_key[r.category, r.key].append(r)
    lines = ["", f"## What blocks the {len(blocked)} cases mech cannot run (the first blocking construct, error "
             "or crash of each)", "", "| rank | construct or message | kind | cases | for example |",
             "|---|---|---|---|---|"]
    ranked = sorted(by_key.items(), key=lambda kv: (-len(kv[1]), kv[0]))
    for k, ((cat, key), rs) in enumerate(ranked[:top], 1):
        ex = ", ".join(f"`{r.name}`" for r in sorted(rs, key=lambda r: r.name)[:3])
        lines.append(f"| {k} | {_md(key)} | {cat} | {len(rs)} | {ex} |")
    if len(ranked) > top:
        rest = ranked[top:]
        lines.append(f"| | {len(rest)} more | | {sum(len(rs) for _, rs in rest)} | |")
    return lines


def _md(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")
