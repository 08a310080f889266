-- the list library: sums, selections, sorting, sets, reshaping
R = QQ[x,y,z];
print sum {1,2,3}
print toString sum({x,y}, i -> i^2)
print product(4, i -> i+1)
print toString select({1,2,3,4}, odd)
print toString select({1,2,3,4}, i -> i > 2)
scan({1,2}, i -> print i)
print any({1,2}, i -> i > 1)
print all({1,2}, i -> i > 1)
print toString sort {3,1,2}
print toString sort {x^2, y, x, z^3, 1}
print max {3,1,2}
print toString set {1,2,2}
print toString flatten {{1,2},{3}}
print toString toList (1,2)
print toString apply(3, i -> i^2)
print toString applyTable({{1,2},{3,4}}, i -> 2*i)
print same {1,1}
print isSubset({1}, {1,2})
print isSubset(ideal(x^2), ideal(x))
print toString unique {1,2,1}
print toString reverse {1,2,3}
print toString take({1,2,3,4}, 2)
print toString drop({1,2,3,4}, {1,2})
print toString position({1,2,3}, i -> i > 1)
print toString positions({1,2,3}, i -> i > 1)
print member(2, {1,2})
print toString tally {1,1,2}
print toString subsets({1,2,3}, 2)
print toString apply({1,2},{3,4}, (a,b) -> a*b)
print toString sum((ideal(x,y))_*)
print toString max(x, y)
print toString set {3,1,2}
print toString set {"b","a"}
R=QQ[x,y];
print toString set {ideal(y), ideal(x)}
needsPackage "MinimalPrimes";
print toString needsPackage "MinimalPrimes"
