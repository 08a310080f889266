-- selectInSubring with elimination and block orders
R = QQ[a..i, MonomialOrder => Eliminate 3];
I = ideal(a^2, b-f, d^4, i - b);
print toString selectInSubring(1, gens gb I)
R = QQ[a..i, MonomialOrder => {Weights => {1,1,1}, 2, 4}];
I = ideal(a..i);
print toString selectInSubring(1, gens gb I)
print toString selectInSubring(2, gens gb I)
print toString selectInSubring(3, gens gb I)
R = ZZ/101[symbol a..symbol d];
print toString monomialCurveIdeal(R,{1,2,3})
R = ZZ/(101)[x,y];
print toString gens R
p=7;
S=ZZ/p[t];
print toString (8*t)
