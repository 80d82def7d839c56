Include "rectangle.geo";
