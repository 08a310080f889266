"""The interpreter's own commands (``print``, ``defined``, ``nameof``, ``reservedName``, ``execute``, ``option``,
``system``, ``export``, ``ERROR``, ``ASSUME``) and the help texts of the language's keywords and types (``help if;``)."""
from __future__ import annotations

from typing import Any

from ..dsl import ast as A
from ..dsl.errors import MechNameError, MechRuntimeError, MechTypeError
from ..dsl.printing import print_form, render
from ..dsl.highlight import KEYWORDS, type_words
from ..dsl.registry import TOPICS, command, is_builtin
from ..dsl.values import NONE, Map, Ring


@command("print")
def print_(ctx, x: Any) -> None:
    """print(x): print x (a matrix as aligned rows, an ideal or intvec as a column).

    Example:
      ring r = 0,(x,y),dp;
      matrix M[2][2] = x,y2,1,-1;
      print(M);
      → x,y2,
      → 1,-1
      print(ideal(x, y));
      → x,
      → y
    """
    if x is NONE:
        return
    if isinstance(x, Map):  # as Singular: a map prints as phi[i]=... under its name
        ctx.write(render(x, ctx.argnames[0] if ctx.argnames else None) + "\n")
        return
    name = ctx.argnames[0] if ctx.argnames and ctx.argnames[0].isidentifier() else "_"
    ctx.write(print_form(x, name) + "\n")


@command("dbprint")
def dbprint(ctx, level: Any, *xs: Any) -> None:
    """dbprint(i, x, ...): print each x as print does when the int i is positive (procedures pass
    printlevel-voice+2, so that printlevel switches their messages on); dbprint(x): print x when
    printlevel >= voice.

    Example:
      int debug = 1;
      dbprint(debug, "step 1");
      → step 1
      dbprint(0, "hidden");
    """
    if not xs:  # dbprint(x): print x when printlevel >= voice
        level, xs = int(ctx.sysvars.get("printlevel", 0) >= len(ctx.frames)), (level,)
    if not isinstance(level, int) or level <= 0:
        return
    for x in xs:
        print_(ctx, x)


@command("defined", raw=True)
def defined(ctx, node: A.Expr) -> int:
    """defined(x): 0 if x is undefined, -1 for a ring variable or a value that is no name, else 1 + the
    level it was declared at.

    Example:
      ring r = 0,(x,y),dp;
      int n = 3;
      defined(n);
      → 1
      defined(x);
      → -1
      defined(m);
      → 0
    """
    if not isinstance(node, A.Name):
        return -1
    var = ctx.lookup(node.id)
    if var is not None:
        return var.level + 1
    ring = ctx.ring
    if ring is not None and (ring.var_index(node.id) is not None or node.id in ring.params):
        return -1
    return 0


@command("nameof", raw=True)
def nameof(ctx, node: A.Expr) -> str:
    """nameof(x): the name of the variable x ("" for an expression; for basering or an expression
    giving a ring, the ring's name).

    Example:
      ring r = 0,(x,y),dp;
      poly f = x+y;
      nameof(f);
      → f
    """
    if isinstance(node, A.Name) and node.id == "basering":
        return ctx.ring.name if ctx.ring is not None else "basering"  # as Singular without a ring
    if isinstance(node, A.Name):
        return node.id
    v = ctx.eval(node)  # an expression: a ring has its name (nameof(preimage(phi)))
    return v.name if isinstance(v, Ring) else ""


@command("reservedName")
def reserved_name(name: str) -> int:
    """reservedName(s): 1 if the word s is reserved by the language (a keyword, a type or a command
    available without a library), else 0.

    Example:
      reservedName("ring");
      → 1
      reservedName("xyz");
      → 0
    """
    return int(name in KEYWORDS or name in type_words() or is_builtin(name))


@command("execute")
def execute(ctx, code: str) -> None:
    """execute(s): run the statements of the string s where execute is called.

    Example:
      int a = 1;
      execute("a = a + 41; a;");
      → 42
    """
    if code.strip() and not code.rstrip().endswith((";", "}")):
        code = code.rstrip() + ";"  # as Singular: the last statement's ';' may be left out
    ctx.execute_here(code)


@command("option", raw=True)
def option(ctx, *nodes: A.Expr) -> None:
    """option(name, ...): set options (option(redSB); option(noredSB) clears one); option() prints them.

    Example:
      ring r = 0,(x,y),dp;
      option(redSB);
      option();
      → //options: redSB redTail redThrough intStrategy redefine usage prompt
    """
    from ..dsl.options import OPTION_ORDER, shown_options
    if not nodes:
        ctx.write("//options: " + " ".join(shown_options(ctx.options, ctx.explicit_options, ctx.ring)) + "\n")
        return
    for n in nodes:
        if not isinstance(n, (A.Name, A.StrLit)):
            raise MechTypeError("option(...) takes option names, e.g. option(redSB) or option(\"redSB\")")
        name = n.id if isinstance(n, A.Name) else n.value
        if name.startswith("no") and name[2:] in OPTION_ORDER:
            ctx.options.discard(name[2:])
            ctx.explicit_options.discard(name[2:])
            continue
        if name not in OPTION_ORDER:
            raise MechNameError(f"unknown option '{name}'")
        ctx.options.add(name)
        ctx.explicit_options.add(name)


@command("test")
def test(ctx, *bits: int) -> None:
    """test(k, ...): Singular's old way to set options by bit number (k >= 0 sets bit k, -k clears it);
    option(name) is the one to use.

    Example:
      ring r = 32003,(x,y),ls;
      test(0, 15);
      option();
      → //options: prot 15 redefine usage prompt
    """
    from ..dsl.options import OPTION_BITS
    for k in bits:  # (Singular also prints a note now and then: "Gerhard, use the option command")
        name = OPTION_BITS.get(abs(k), str(abs(k)))
        if name is None:
            continue
        if k < 0:
            ctx.options.discard(name)
            ctx.explicit_options.discard(name)
        else:
            ctx.options.add(name)
            ctx.explicit_options.add(name)


@command("system")
def system(ctx, what: str, *args: Any) -> Any:
    """system("--ticks-per-sec", n): the unit of timer and rtimer (ticks per second).

    Example:
      system("--ticks-per-sec", 1000);
    """
    if what == "--ticks-per-sec":
        if args:
            n = args[0]
            if not isinstance(n, int) or n <= 0:
                raise MechRuntimeError('system("--ticks-per-sec", n) needs a positive int')
            ctx.ticks_per_sec = n
            return None
        return ctx.ticks_per_sec
    raise MechRuntimeError(f"system(\"{what}\") is not supported")


@command("export", raw=True)
def export(ctx, *nodes: A.Expr) -> None:
    """export(x): make a procedure's variable x global (with its ring).

    Example:
      proc mk() { int k = 7; export(k); }
      mk();
      k;
      → 7
    """
    for n in nodes:
        if not isinstance(n, A.Name):
            raise MechTypeError("export needs variable names")
        ctx.export(n.id)


@command("ERROR")
def error_(ctx, message: str) -> None:
    """ERROR(s): stop with the error message s (in a procedure: the procedure and its callers).

    Example:
      int k = 2;
      if (k > 3) { ERROR("k is too large"); }
      k;
      → 2
    """
    raise MechRuntimeError(str(message))


@command("ASSUME")
def assume(ctx, level: int, holds: int) -> None:
    """ASSUME(level, cond): stop with an error when the int cond is 0 and level is 0 (checks of a
    higher level are off, as in Singular by default).

    Example:
      ASSUME(0, 2 + 2 == 4);
      ASSUME(1, 0);
      "checked";
      → checked
    """
    if level <= 0 and not holds:
        line = ctx.source.line(ctx.stmt.pos.line + ctx.line_shift).strip() if ctx.stmt else ""
        raise MechRuntimeError(f"ASSUME failed:{line}")


# ---------------------------------------------------------------- help topics of the language
TOPICS.update({
    "if": "if (cond) { ... } else { ... }: run the first block when the int cond is not 0, else the second.",
    "else": "if (cond) { ... } else { ... }: the block run when cond is 0.",
    "for": "for (init; cond; step) { ... }: run init, then the block and step while the int cond is not 0.",
    "while": "while (cond) { ... }: run the block while the int cond is not 0.",
    "break": "break;: leave the innermost for or while loop.",
    "continue": "continue;: go on with the next round of the innermost loop.",
    "proc": "proc name(type a, ..., list #) { ... }: define a procedure; its variables are local, "
            "return(...) gives its values.",
    "return": "return(v, ...);: leave the procedure with the values v, ...",
    "kill": "kill x, ...;: delete the variables x, ...",
    "export": "export x;: make the procedure's variable x a top-level variable (of its ring).",
    "keepring": "keepring r;: leave the procedure with r as the basering.",
    "setring": "setring r;: make the ring r the basering (objects of other rings become invisible).",
    "LIB": 'LIB "x.lib";: load the library x.lib (mech\'s own libraries or a file next to the script).',
    "quit": "quit;: end the script.",
    "exit": "exit;: end the script.",
    "help": "help NAME; or ?NAME;: what a command, procedure, type or keyword does; help; lists the commands.",
    "basering": "basering: the current ring.",
    "int": "int i = 3;: a machine integer (div, mod, % and / divide; comparisons give 0 or 1).",
    "bigint": "bigint b = 2^70;: an integer of any size like int, with Euclidean div and mod.",
    "number": "number c = 3/4;: an element of the coefficient field of the basering.",
    "poly": "poly f = x2+y;: a polynomial of the basering.",
    "ring": "ring r = 0, (x,y,z), dp;: a polynomial ring (characteristic or (char, params), variables, "
            "ordering); it becomes the basering.",
    "map": "map phi = r, f1, ..., fn;: the map from ring r to the basering taking the i-th variable to fi.",
    "list": "list L = a, b, ...;: a list of values of any types; L[i] is the i-th entry.",
    "string": 'string s = "abc";: a string; + concatenates, s[i] is a character.',
    "intvec": "intvec v = 1, 2, 3..5;: a vector of ints.",
    "def": "def x = value;: a variable taking the type of its value.",
})
