#version 120
// Depth only: the depth attachment is written without any help from us.
void main()
{
}
