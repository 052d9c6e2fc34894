// A call into `upper`: allowed only where the fixture declares that lower uses upper.
int upper_answer();
int lower_answer() {
  return upper_answer() + 1;
}
