#version 330 core
// Depth only: the fixed pipeline writes the depth attachment.
void main()
{
}
