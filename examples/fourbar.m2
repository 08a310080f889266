-- Section 4.2 of the paper: the closed four-bar, ground bar of length 1, in Macaulay2's syntax
-- (run: mech examples/fourbar.m2; Singular's version: the paper's fourbar.sing).
R = QQ[c1,s1,c2,s2,c3,s3,l1,l2,l3, MonomialOrder => {GRevLex => 6, GRevLex => 3}];
J = ideal(l1*c1+l2*c2+l3*c3-1, l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1);
D = matrix apply(first entries gens J, f -> apply({c1,s1,c2,s2,c3,s3}, v -> diff(v, f)));
F = minors(5, D);
L = minimalPrimes F;
#L                                               -- 10 prime components
L
S = J + ideal(-s2*c3+c2*s3, -s1*c3+c1*s3, -s1*c2+c1*s2);  -- relevant component
E = eliminate({c1,s1,c2,s2,c3,s3}, S)
factor E_0                                       -- the 8 factors l1 +- l2 +- l3 +- 1
-- l1 = l2 = l3 = 1
R1 = QQ[c1,s1,c2,s2,c3,s3];
J = ideal(c1+c2+c3-1, s1+s2+s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1);
dim J                                            -- 1
P = primaryDecomposition J                       -- three motion modes
Q = minimalPrimes(J + ideal(-s2*c3+c2*s3, -s1*c3+c1*s3, -s1*c2+c1*s2))  -- three singular points
-- q1 = (-1,0,1,0,1,0) to the origin
Jq = sub(J, {c1 => c1-1, c2 => c2+1, c3 => c3+1});
T = tangentCone Jq                               -- V(c1,c2,c3, s1+s2+s3, s2*s3): two lines
Rl = QQ[c1,s1,c2,s2,c3,s3, MonomialOrder => {Weights => {-1,-1,-1,-1,-1,-1}}, Global => false];
Jl = sub(Jq, Rl);
Ll = minimalPrimes Jl                            -- two local components meet at q1
