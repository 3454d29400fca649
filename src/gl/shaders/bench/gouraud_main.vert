void main() {
    vec3 P = vec3(model * vec4(aPos, 1.0));
    vec3 N = mat3(transpose(inverse(model))) * aNormal;
    Color = shade(P, N);
    gl_Position = projection * view * vec4(P, 1.0);
}
