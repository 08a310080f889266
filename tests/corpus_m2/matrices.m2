-- matrices, substitution, factorization
R = QQ[x,y,z];
M = matrix {{x, y, z}, {y, z, x}};
print toString M
print toString minors(2, M)
print toString jacobian ideal(x^2 - y, x*y - z)
print toString jacobian matrix {{x^2*y + z}}
print toString det matrix {{x, y}, {z, x}}
print toString minors(2, jacobian ideal(x^2 + y^2 - 1, x*y - z))
print toString transpose M
print toString sub(x^2 - y + z, {x => 1, y => z})
print toString sub(ideal(x^2 - y, x*y - z), {x => 2*y})
print toString factor(x^2 - y^2)
print toString factor(x^4 - 1)
print toString factor(2*x^2 - 2)
print toString diff(x, x^3*y + y*z)
print numgens ideal(x, y, z)
print toString first entries gens ideal(x, y)
