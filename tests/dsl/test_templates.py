"""Statement templates (mech.dsl.templates): lines that differ only in their numbers run by one tree
and closure, with the output, warnings and error positions of each line parsed on its own."""
import pytest

from mech.dsl import ast as A
from mech.dsl.parser import parse
from mech.dsl.templates import make, shape

from tests.dsl.test_fastparse import run_script

SCRIPTS = [  # the error comes after numbers of other lengths than the template's
    "int k = 3; int j;\nj = k div 12 + k div 1 + 1;\nj = k div 1 + k div 12 + 1;\nj = k div 123 + k div 00 + 1;\n",
    "int k = 3; int j;\nproc p(int a) { return (k div a); }\nj = 1 + p(1) + 22;\nj = 11 + p(11) + 2;\n"
    "j = 123 + p(0) + 222;\n",
    "ring r = 0,(x,y),dp; poly f;\nf = 3x2y + 1/2;\nf = 17x2y + 31/5;\nf;\nf = 3/4x + 2;\nf = 13/14x + 25;\n"
    "f = 1/2 + x;\nf = 10/3 + x;\nf;\nf = 100/0 + x;\n",
    "int m = 5;\nint m = 6;\nm;\nint m = 77; m;\n",  # "redefining" warnings name their line
    "ring r = 0,(x,y),dp;\nideal I = x, 5;\nI[2] = x2 - 7;\nI[3] = x2 - 71;\nI;\nI[12] = 1; I;\n"
    "intvec v = 1,2,3; v[2] = 9; v[3] = 8; v;\nv[5] = 4;\nv[6] = 44;\nv;\nv[0] = 1;\n",
    "int k = 2;\nk + 3;\nk * 45, 6;\nstring(12);\nstring(k, 3);\nsize(list(1, 2, 3));\nk++; k;\n"
    "list L = 1, 2; L[2] = 33; L[3] = 4; L; kill L;\nlist L = 12, 2;\nL;\n",
    "ring r = 0,(x,y),dp; matrix M[2][2];\nM[1,2] = x + 1;\nM[2,1] = x + 12;\nprint(M);\nM[3,1] = x;\n",
    "int i = 1;\nint j = 2147483647 + 1;\ni = 123456789012345678 * 10;\ni = 1 + 1234567890123456789012;\ni;\n"
    "i = 5..7;\ni = 5..8;\n",
    "int k = 3; int j;\nif (k > 1) { j = 2; } else { j = j + 1; }\nif (k > 12) { j = 23; } else { j = j + 14; }\nj;\n"
    "for (int i = 1; i <= 2; i++) { j = j + i; }\nfor (int i = 1; i <= 23; i++) { j = j + i; }\nj;\n"
    "while (j > 100) { j = j - 7; }\nwhile (j > 10) { j = j - 17; }\nj;\n"
    "if (k > 1) { j = 10 div 1; } else { j = 1; }\nif (k > 12) { j = 1; } else { j = 1 + 10 div 0; }\n",
    "int k = 1;\nif (k > 5) { k = 2; break; }\nif (k > 55) { break; }\nif (k > 0) { k = 2; break; }\n",
    "int k = 1;\nfor (k = 1; k < 3; k++) { if (k > 5) { continue; } }\nfor (k = 11; k < 13; k++) { k; }\n"
    "{ k = 1; }\n{ k = 23; }\nk;\nif (k) { continue; }\n",
    "ring r = 0,(x(1..3)),dp;\npoly f = x(1) + x(2);\npoly g = x(2) + x(3);\nf; g;\ng = x(4);\n",
    # monomial literals: their monomial found once per ring, the others' and the errors' as alone
    "ring r = 0,(x,y),dp; poly f;\nf = 3x2y - 1/2y;\nf = 17x2y - 5/3y;\nf;\nring s = 7,(y,x),ds; poly f;\n"
    "f = 3x2y - 1/2y;\nf = 17x2y - 5/3y;\nf;\nring t = (0,a),(x,y),dp; poly f;\nf = 3x2y - 1/2y;\n"
    "f = 3ax2 - 1/2y;\nf = 17ax2 - 5/3y;\nf;\nf = 2ax2 - 1/0y;\n",
    "ring r = 0,(x,y),dp; poly f;\nf = 3x2 - 1/2y;\nf = 17x2 - 5/3y;\nring s = 0,(z,y),dp; poly f;\n"
    "f = 3x2 - 1/2y;\n",
]


@pytest.mark.parametrize("text", SCRIPTS)
def test_templates_run_as_each_line_alone(text, monkeypatch):
    import mech.dsl.fastparse as fp
    fp._SHARED.clear()
    shared = run_script(text)
    monkeypatch.setattr(fp, "MAX_SHARED", 0)
    assert shared == run_script(text)
    assert "error" in shared or "//" in shared or shared.count("\n") > 3


def test_lines_of_one_shape_share_a_template():
    import mech.dsl.fastparse as fp
    fp._SHARED.clear()
    program = parse("int k;\nk = k + 1;\nk = k + 22;\nk = k + 333;\n", shared=True)
    a, b, c = program.body[1:]
    assert not isinstance(a, A.Relit)
    assert isinstance(b, A.Relit) and isinstance(c, A.Relit) and b.template is c.template
    assert (c.lits, c.dline, c.pos) == (["333"], 1, A.Pos(4, 1, 4, 13))


def test_shapes():
    assert shape("k = k + 12;") == ("k = k + \0;", ["12"])
    assert shape("f = 3x2y - 1/2;") == ("f = \0x2y - \0/\0;", ["3", "1", "2"])
    assert shape("k = x1 + y;") is None
    assert shape('s = "12";') is None and shape("k = 1; // 2") is None


def test_numbers_that_are_not_whole_literals_refuse_a_template():
    tree = parse("int k = 12;").body[0]
    assert make(tree, "int k = 12;", 1, ["12"]) is not None
    assert make(tree, "int k = 123;", 1, ["123"]) is None  # the literal's span is not the number's
    assert make(tree, "int k = 12 ;", 2, ["12"]) is None
