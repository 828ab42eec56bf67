// Must NOT compile: a capacity N < 3 holds no three-node rule, and gauss_three_nodes says so
// (the ctest build.three_node_rule_refuses_capacity_2 expects its static_assert message).
#include <fluidbed/moments/jacobi_eigen.hpp>

int main() { return fluidbed::moments::gauss_three_nodes(fluidbed::moments::Recurrence<double, 2>{}).size; }
