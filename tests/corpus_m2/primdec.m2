-- decompositions (component order may differ: compared as sets)
R = QQ[x,y,z];
print toString radical ideal(x^2*y, x*y^2)
print toString radical ideal(x^3 - y^2, y^3)
print toString minimalPrimes ideal(x*y, x*z)
print toString decompose ideal(x^2 - y^2, x*z)
print toString associatedPrimes ideal(x^2, x*y)
print toString primaryDecomposition ideal(x*y, x*z)
print toString primaryDecomposition ideal(x^2 - 1, y^2 - 1)
print toString minimalPrimes ideal(x^2 + y^2 - 1, x - y)
print isPrime ideal(x^2 - y)
print isPrime ideal(x*y)
print isPrimary ideal(x^2, y)
print isPrimary ideal(x*y)
S = QQ[c1,s1,c2,s2];
J = ideal(s1 + s2, c1^2 + s1^2 - 1, c2^2 + s2^2 - 1);
print(#(minimalPrimes J))
print toString minimalPrimes (J + ideal(c1, c2))
