/* Linked with every object of the GL-free library (--whole-archive) and nothing of the GL
 * side: the link fails, naming the symbol, when a core file comes to call the GL side,
 * the platforms or the commands. Built by make check; it does nothing when run. */
int main(void) { return 0; }
