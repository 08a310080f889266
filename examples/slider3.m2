-- Section 4.1.2 of the paper: the 3-bar slider-crank, in Macaulay2's syntax
-- (run: mech examples/slider3.m2; Singular's version: the paper's slider3.sing).
R = QQ[c1,s1,c2,s2,c3,s3,l1,l2,l3, MonomialOrder => {GRevLex => 6, GRevLex => 3}];
J = ideal(l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1);
D = matrix apply(first entries gens J, f -> apply({c1,s1,c2,s2,c3,s3}, v -> diff(v, f)));
F = minors(4, D);
L = minimalPrimes F;
#L                                               -- 11 prime components
L
S = J + ideal(c1, c2, c3);                       -- relevant component J_9 = <c1,c2,c3>
E = eliminate({c1,s1,c2,s2,c3,s3}, S)
factor E_0                                       -- (l1+l2+l3)(l1-l2-l3)(l1+l2-l3)(l1-l2+l3)
-- l1 = 2, l2 = l3 = 1
R1 = QQ[c1,s1,c2,s2,c3,s3];
J = ideal(2*s1+s2+s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1);
dim J                                            -- 2
Q = minimalPrimes(J + ideal(c1, c2, c3))         -- singular points q1, q2
-- q2 = (0,-1,0,1,0,1) to the origin
Jq = sub(J, {s1 => s1-1, s2 => s2+1, s3 => s3+1});
T = tangentCone Jq                               -- V(s1,s2,s3, 2c1^2-c2^2-c3^2): a quadric cone
Rl = QQ[c1,s1,c2,s2,c3,s3, MonomialOrder => {Weights => {-1,-1,-1,-1,-1,-1}}, Global => false];
Jl = sub(Jq, Rl);
Ll = minimalPrimes Jl                            -- ONE local component: an irreducible singularity
