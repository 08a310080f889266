-- PrimaryDecomposition and MinimalPrimes: components, localization, irreducible decompositions
R = QQ[x,y,z];
I = intersect(ideal(x), (ideal(y,z))^2, (ideal(x,y,z))^3);
print toString topComponents I
print toString removeLowestDimension I
print toString removeLowestDimension ideal(x*y)
print toString minprimes I
print toString ass I
print toString primaryComponent(I, ideal(y,z))
print toString primaryComponent(ideal(x^2, x*y), ideal(x))
print toString irreducibleDecomposition monomialIdeal(x^2, x*y, y^3)
print toString localize(I, ideal(y,z))
