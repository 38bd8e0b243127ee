  // VTK Stylize G-buffer outputs, written after lighting. The pass keeps the line of each
  // channel it allocated and puts in the attachment index and the value (the index must be a
  // literal: VTK's shader cache maps gl_FragData[i] to its outputs by text).
  // Alpha 1 marks a surface sample, alpha 0 a primitive without normal or position (unlit lines,
  // points), whose linear depth is -1; the background keeps the cleared value 0.
  gl_FragData[NORMAL_INDEX] = NORMAL_VALUE;
  gl_FragData[POSITION_INDEX] = POSITION_VALUE;
  gl_FragData[LINEAR_DEPTH_INDEX] = LINEAR_DEPTH_VALUE;
  gl_FragData[DIRECTION_INDEX] = DIRECTION_VALUE;
