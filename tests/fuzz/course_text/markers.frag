void main() {
    // BEGIN SOLUTION
    float m = 0.01;
    // END SOLUTION
    // STUB: float m = 0.0;
}
