  // VTK Stylize: facet normal from screen-space derivatives, in uniform control flow.
  vec3 stylizeFaceN = cross(dFdx(vertexVC.xyz), dFdy(vertexVC.xyz));
