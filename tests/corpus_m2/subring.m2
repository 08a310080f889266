-- selectInSubring with elimination and block orders
R = QQ[a..i, MonomialOrder => Eliminate 3];
I = ideal(a^2, b-f, d^4, i - b);
print toString selectInSubring(1, gens gb I)
R = QQ[a..i, MonomialOrder => {Weights => {1,1,1}, 2, 4}];
I = ideal(a..i);
print toString selectInSubring(1, gens gb I)
print toString selectInSubring(2, gens gb I)
print toString selectInSubring(3, gens gb I)
