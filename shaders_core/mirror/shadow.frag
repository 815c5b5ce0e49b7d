#version 330 core
// Depth only: the depth attachment is written without any help from us.
void main()
{
}
