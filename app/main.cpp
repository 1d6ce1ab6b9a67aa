#include <cstdio>
int main() { std::puts("raylab"); return 0; }
