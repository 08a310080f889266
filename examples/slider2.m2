-- Section 4.1.1 of the paper: the 2-bar slider-crank, in Macaulay2's syntax
-- (run: mech examples/slider2.m2; Singular's version: the paper's slider2.sing).
-- global analysis with the link lengths as variables (elimination order: angles first)
R = QQ[c1,s1,c2,s2,l1,l2, MonomialOrder => {GRevLex => 4, GRevLex => 2}];
J = ideal(l1*s1+l2*s2, c1^2+s1^2-1, c2^2+s2^2-1);
D = submatrix(transpose jacobian J, {0,1,2,3});  -- derivatives by the angles
F = minors(3, D);                                -- Fitting ideal I_3(dp)
L = minimalPrimes F;
#L                                               -- 6 prime components
L
S = J + ideal(c1, c2);                           -- the physically relevant component
E = eliminate({c1,s1,c2,s2}, S)                  -- condition on the lengths: l1^2-l2^2
-- l1 = l2 = 1
R1 = QQ[c1,s1,c2,s2];
J = ideal(s1+s2, c1^2+s1^2-1, c2^2+s2^2-1);
dim J                                            -- 1
Q = minimalPrimes(J + ideal(c1, c2))             -- the two singular points
P = primaryDecomposition J                       -- two motion modes c1=c2 and c1=-c2
-- local analysis at q2 = (c1,s1,c2,s2) = (0,-1,0,1): move q2 to the origin
Jq = sub(J, {s1 => s1-1, s2 => s2+1});
T = tangentCone Jq                               -- V(s1,s2,c1^2-c2^2): two lines
Rl = QQ[c1,s1,c2,s2, MonomialOrder => {Weights => {-1,-1,-1,-1}}, Global => false];
Jl = sub(Jq, Rl);
Ll = minimalPrimes Jl                            -- two local components meet at q2
