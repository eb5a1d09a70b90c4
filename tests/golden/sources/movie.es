#javascript
Builder.load("frame.es");
for (var i = 1; i <= 3; i++) {
  Builder.reset();
  Builder.define("n", i);
  Builder.build();
  Builder.raytraceToFile("f" + i + ".png", true);
}
