#version 120
// Depth only: the fixed pipeline writes the depth attachment.
void main()
{
}
