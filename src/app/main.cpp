// The crumple command. Placeholder until the application layer lands.
int main() { return 0; }
