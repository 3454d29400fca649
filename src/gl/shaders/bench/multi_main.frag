void main() { FragColor = vec4(shade(FragPos, Normal), 1.0); }
